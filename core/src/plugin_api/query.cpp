#include <collido/query.h>

namespace collido {

const char* queryKindName(QueryKind kind) {
  switch (kind) {
    case QueryKind::kBoolean:
      return "boolean";
    case QueryKind::kAllPairs:
      return "all_pairs";
    case QueryKind::kContacts:
      return "contacts";
    case QueryKind::kDistance:
      return "distance";
  }
  return "unknown";
}

std::optional<QueryKind> parseQueryKind(const std::string& name) {
  for (QueryKind kind : kAllQueryKinds) {
    if (name == queryKindName(kind)) return kind;
  }
  return std::nullopt;
}

std::string queryKindsText(QueryKindSet set) {
  std::string text;
  for (QueryKind kind : kAllQueryKinds) {
    if (!set.contains(kind)) continue;
    if (!text.empty()) text += ", ";
    text += queryKindName(kind);
  }
  return text.empty() ? "nothing" : text;
}

}  // namespace collido
