#include <collido/runner/text_table.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace collido {

std::string formatNumber(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), pattern, value);
  return buffer;
}

std::string bytesPerTriangleText(std::size_t bytes, std::size_t triangles) {
  if (triangles == 0) return "-";
  return formatNumber("%.0f", static_cast<double>(bytes) / static_cast<double>(triangles));
}

namespace {

// Columns line up on screen: a UTF-8 character ("≈", "µ") takes one column, not its bytes.
std::size_t columnsOf(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char byte) {
    return (static_cast<unsigned char>(byte) & 0xC0u) != 0x80u;
  }));
}

}  // namespace

std::string formatTextTable(const std::vector<std::string>& header,
                            const std::vector<std::vector<std::string>>& rows,
                            std::size_t first_numeric) {
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    width[c] = columnsOf(header[c]);
    for (const auto& row : rows)
      if (c < row.size()) width[c] = std::max(width[c], columnsOf(row[c]));
  }
  std::ostringstream out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < header.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      const std::string pad(width[c] - columnsOf(cell), ' ');
      out << (c == 0 ? "" : "  ") << (c >= first_numeric ? pad + cell : cell + pad);
    }
    out << "\n";
  };
  line(header);
  std::size_t total = 0;
  for (std::size_t w : width)
    total += w + 2;
  out << std::string(total - 2, '-') << "\n";
  for (const auto& row : rows)
    line(row);
  return out.str();
}

}  // namespace collido
