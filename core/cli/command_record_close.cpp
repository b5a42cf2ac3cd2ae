// collido record-close: writes a recording's scene from the frames its journal completed, for a
// recording whose application ended without closing it (a crash, a kill).
#include <iostream>

#include <collido/record/recorder.h>

#include "commands.h"

namespace collido::cli {

void addRecordCloseCommand(CLI::App& app, int& exit_code) {
  auto folder = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "record-close",
      "Write a recording folder's scene.json from its journal's completed frames (a frame cut "
      "short is left out)");
  command->add_option("FOLDER", *folder, "a folder collido::Recorder wrote")->required();
  command->callback([folder, &exit_code] {
    try {
      const std::size_t frames = closeRecording(*folder);
      std::cout << *folder << "/scene.json: " << frames << " frame" << (frames == 1 ? "" : "s")
                << "\n";
      exit_code = 0;
    } catch (const RecordError& e) {
      std::cerr << "error: " << e.what() << "\n";
      exit_code = 2;
    }
  });
}

}  // namespace collido::cli
