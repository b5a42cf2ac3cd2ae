// Base64 for data URIs, through Boost.Serialization's header-only iterators.
#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>

#include <collido/io/html_page.h>

namespace collido::io {

std::string base64(const std::string& bytes) {
  using namespace boost::archive::iterators;  // NOLINT(google-build-using-namespace)
  using Encoder = base64_from_binary<transform_width<std::string::const_iterator, 6, 8>>;
  std::string text(Encoder(bytes.begin()), Encoder(bytes.end()));
  // The iterators stop at the last 6-bit group; padding completes the last 4-character block.
  text.append((3 - bytes.size() % 3) % 3, '=');
  return text;
}

}  // namespace collido::io
