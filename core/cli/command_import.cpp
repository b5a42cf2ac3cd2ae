// collido import urdf: a robot described in URDF written as a scene (collido/urdf/urdf_import.h).
#include <iostream>

#include <collido/urdf/urdf_import.h>

#include "commands.h"

namespace collido::cli {

void addImportCommand(CLI::App& app, int& exit_code) {
  CLI::App* command = app.add_subcommand("import", "Write a scene from another description");
  command->require_subcommand(1);
  CLI::App* urdf = command->add_subcommand(
      "urdf",
      "A robot in URDF as a scene: its links' collision geometry as objects mounted on their "
      "parents, its joints driving the frames; self-collision of every link pair but adjacent "
      "ones and those in contact at the reference configuration, robot against environment, and "
      "the clearance of its last link or the --clearance links (scenes/README.md, \"Robots from "
      "URDF\")");
  auto request = std::make_shared<UrdfImportRequest>();
  auto environment = std::make_shared<std::vector<std::string>>();
  urdf->add_option("robot", request->urdf, "the URDF file")->required();
  urdf->add_option("--trajectory", request->trajectory,
                   "joints CSV: a header of joint names, one row of values per frame (radians, "
                   "metres); default: seeded random configurations within the limits");
  urdf->add_option("--environment", *environment,
                   "mesh files fixed in the world, each FILE or FILE@X,Y,Z or "
                   "FILE@X,Y,Z,ROLL,PITCH,YAW to place it (metres, radians: URDF's xyz and rpy)");
  urdf->add_option("-o,--output", request->output, "the scene file to write")->required();
  urdf->add_option("--frames", request->frames, "random configurations (default 24)")
      ->check(CLI::Range(1, 1000000));
  urdf->add_option("--seed", request->seed, "their seed (default 1)");
  urdf->add_option("--disable-pair", request->disable_pairs,
                   "LINK LINK: a pair never asked for self-collision (repeatable)");
  urdf->add_option("--enable-pair", request->enable_pairs,
                   "LINK LINK: a pair asked whatever the rules say (repeatable)");
  urdf->add_option("--clearance", request->clearance_links,
                   "LINK: ask its distance to each environment object (repeatable; default: the "
                   "link with the most joints above it)");
  urdf->add_option("--first-contact", request->first_contact_links,
                   "LINK: ask its first contact with each environment object over every step "
                   "from a frame to the next (repeatable)");
  urdf->add_flag("--first-contact-only", request->first_contact_only,
                 "ask the --first-contact queries alone, not self-collision, the environment and "
                 "clearance at the frames");
  urdf->callback([request, environment, &exit_code] {
    if (Status s = parseEnvironmentMeshes(*environment, request->environment); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      exit_code = 2;
      return;
    }
    const Result<UrdfImport> imported = importUrdf(*request);
    if (!imported.ok()) {
      std::cerr << "error: " << imported.status().message() << "\n";
      exit_code = 2;
      return;
    }
    const UrdfImport& i = imported.value();
    std::cout << request->output << ": robot '" << i.robot << "', " << i.objects << " objects, "
              << i.moving_joints << " moving joints, " << i.frames << " frames; " << i.self_pairs
              << " object pairs asked for self-collision (left out: " << i.adjacent_pairs
              << " adjacent link pairs, " << i.touching_pairs
              << " in contact at the reference configuration, " << i.disabled_pairs
              << " disabled)\n";
    exit_code = 0;
  });
}

}  // namespace collido::cli
