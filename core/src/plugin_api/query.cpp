#include <collido/query.h>

#include <cstddef>
#include <cstdint>
#include <iterator>

#include <collido/assert.h>

namespace collido {

namespace {

// The table lists the kinds in the order of their bits, so a kind's entry sits at its bit's
// index: every query call looks its kind up (host and adapter), and a scan would cost that
// call a few comparisons for nothing.
constexpr bool kindsInBitOrder() {
  std::uint32_t bit = 1;
  for (const QueryKindInfo& info : kQueryKinds) {
    if (static_cast<std::uint32_t>(info.kind) != bit) return false;
    bit <<= 1;
  }
  return true;
}
static_assert(kindsInBitOrder(), "kQueryKinds must list the kinds in the order of their bits");

}  // namespace

const QueryKindInfo& queryKindInfo(QueryKind kind) {
  const auto bits = static_cast<std::uint32_t>(kind);
  if (bits != 0 && (bits & (bits - 1)) == 0) {
    const auto index = static_cast<std::size_t>(__builtin_ctz(bits));
    if (index < std::size(kQueryKinds)) return kQueryKinds[index];
  }
  // Every value of the enum has its entry; the plugin adapter refuses any other before this.
  COLLIDO_ASSERT(false, "a query kind without its entry in kQueryKinds");
}

const char* queryKindName(QueryKind kind) {
  for (const QueryKindInfo& info : kQueryKinds) {
    if (info.kind == kind) return info.name;
  }
  return "unknown";
}

std::optional<QueryKind> parseQueryKind(const std::string& name) {
  for (const QueryKindInfo& info : kQueryKinds) {
    if (name == info.name) return info.kind;
  }
  return std::nullopt;
}

std::string queryKindsText(QueryKindSet set) {
  std::string text;
  for (const QueryKindInfo& info : kQueryKinds) {
    if (!set.contains(info.kind)) continue;
    if (!text.empty()) text += ", ";
    text += info.name;
  }
  return text.empty() ? "nothing" : text;
}

}  // namespace collido
