#include <collido/query.h>

#include <collido/assert.h>

namespace collido {

const QueryKindInfo& queryKindInfo(QueryKind kind) {
  for (const QueryKindInfo& info : kQueryKinds) {
    if (info.kind == kind) return info;
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
