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
  }
  return "unknown";
}

}  // namespace collido
