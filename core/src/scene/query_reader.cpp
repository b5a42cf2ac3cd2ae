#include "query_reader.h"

#include "frame_ranges_reader.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace collido::scene_reading {
namespace {

// The names of the kinds `holds` is true of, "a, b or c".
template <typename Predicate>
std::string kindNames(Predicate holds) {
  std::vector<const char*> names;
  for (const QueryKindInfo& kind : kQueryKinds) {
    if (holds(kind)) names.push_back(kind.name);
  }
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += names[i];
  }
  return text;
}

// The bracket width of a kind asked over a step, and its default frames: every frame that has a
// next one (a step from frame k is asked "in frame k").
void readStep(const Reader& r, const Node& node, const QueryKindInfo& kind, const Scene& scene,
              SceneQuery& query) {
  if (!kind.over_a_step) {
    if (node.has("bracket_width")) {
      r.fail(node.at("bracket_width"),
             "bracket_width applies to " +
                 kindNames([](const QueryKindInfo& k) { return k.over_a_step; }) + " queries only");
    }
    return;
  }
  query.request.step.emplace();
  query.request.step->bracket_width = kDefaultBracketWidth;
  if (node.has("bracket_width")) {
    const double width = r.number(node.at("bracket_width"));
    if (!(width > 0.0)) r.fail(node.at("bracket_width"), "bracket_width must be > 0");
    query.request.step->bracket_width = width;
  }
  if (scene.frames < 2) {
    r.fail(node.at("kind"), std::string("a ") + kind.name +
                                " query is asked over a step from one frame to the next: the "
                                "scene needs at least two frames");
  }
  query.asked.ranges = {{0, scene.frames - 2}};
  // The step moves each object rigidly: a shape that changes between frames has no one motion.
  for (const std::size_t object : {query.a, query.b}) {
    if (scene.objects[object].changesShape()) {
      r.fail(node.at("kind"),
             std::string("a ") + kind.name + " query moves its objects rigidly: '" +
                 scene.objects[object].name + "' changes shape (states or movable nodes)");
    }
  }
}

QueryKind readQueryKind(const Reader& r, const Node& node) {
  const std::string text = r.string(node);
  if (const std::optional<QueryKind> kind = parseQueryKind(text)) return *kind;
  r.fail(node, "unknown query kind '" + text +
                   "' (known: " + kindNames([](const QueryKindInfo&) { return true; }) + ")");
}

// The objects a query entry names: "name" (that object) or {"subtree": "name"} (it and every
// object mounted on it), with a label for the query's default name.
struct Selection {
  std::vector<std::size_t> objects;  // ascending
  std::string label;
};

Selection readSelection(const Reader& r, const Node& node, const Scene& scene,
                        const std::map<std::string, std::size_t>& index_of) {
  const auto index = [&](const Node& name_node) {
    const std::string name = r.string(name_node);
    const auto found = index_of.find(name);
    if (found == index_of.end()) r.fail(name_node, "no object named '" + name + "'");
    return found->second;
  };
  if (node.value.is_object()) {
    r.expectObject(node, {"subtree"});
    if (!node.has("subtree")) r.fail(node, "expected {\"subtree\": an object's name}");
    const std::size_t root = index(node.at("subtree"));
    return Selection{scene.subtree(root), scene.objects[root].name + "/*"};
  }
  if (!node.value.is_string()) {
    r.fail(node, std::string("expected an object's name or {\"subtree\": name}, got ") +
                     scene_reading::typeName(node.value));
  }
  const std::size_t object = index(node);
  return Selection{{object}, scene.objects[object].name};
}

// "among": "*" (every object) or an array of object names and subtrees, at least two objects,
// none named twice.
std::vector<std::size_t> readGroup(const Reader& r, const Node& node, const Scene& scene,
                                   const std::map<std::string, std::size_t>& index_of) {
  std::vector<std::size_t> group;
  if (node.value.is_string()) {
    if (r.string(node) != "*") {
      r.fail(node, "'among' is \"*\" or an array of object names and {\"subtree\": name}");
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      group.push_back(i);
  } else {
    r.expectArray(node);
    for (std::size_t i = 0; i < node.value.size(); ++i) {
      for (const std::size_t index : readSelection(r, node.at(i), scene, index_of).objects) {
        if (std::find(group.begin(), group.end(), index) != group.end()) {
          r.fail(node.at(i), "object '" + scene.objects[index].name + "' named twice");
        }
        group.push_back(index);
      }
    }
    std::sort(group.begin(), group.end());
  }
  if (group.size() < 2) r.fail(node, "a group query needs at least two objects");
  return group;
}

// "a" and "b": two objects, or sets (subtrees) of them, asked against each other: a query of
// two objects, or a group query of every pair across the two sets.
void readSides(const Reader& r, const Node& node, const Scene& scene,
               const std::map<std::string, std::size_t>& index_of, SceneQuery& query,
               std::string& label) {
  Selection sides[2];
  for (int k = 0; k < 2; ++k) {
    const char* side = k == 0 ? "a" : "b";
    if (!node.has(side)) r.fail(node, std::string("missing '") + side + "' (or 'among')");
    sides[k] = readSelection(r, node.at(side), scene, index_of);
  }
  label = sides[0].label + "-" + sides[1].label;
  const std::vector<std::size_t>& a = sides[0].objects;
  const std::vector<std::size_t>& b = sides[1].objects;
  if (a.size() == 1 && b.size() == 1) {
    if (a[0] == b[0]) r.fail(node, "a query needs two different objects");
    query.a = a[0];
    query.b = b[0];
    return;
  }
  std::vector<std::size_t> shared;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
  if (!shared.empty()) {
    r.fail(node.at("b"), "object '" + scene.objects[shared.front()].name +
                             "' is on both sides: 'a' and 'b' must not share objects");
  }
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(query.among));
  query.side_b = b;
}

// "except": object pairs of a group query not asked, each two objects the query names.
void readExcept(const Reader& r, const Node& node,
                const std::map<std::string, std::size_t>& index_of, SceneQuery& query) {
  if (!query.isGroup()) {
    r.fail(node, "'except' applies to group queries ('among', or subtrees) only");
  }
  r.expectArray(node);
  for (std::size_t k = 0; k < node.value.size(); ++k) {
    const Node pair = node.at(k);
    r.expectArray(pair);
    if (pair.value.size() != 2) r.fail(pair, "expected two object names");
    std::size_t ends[2];
    for (std::size_t e = 0; e < 2; ++e) {
      const std::string name = r.string(pair.at(e));
      const auto found = index_of.find(name);
      if (found == index_of.end()) r.fail(pair.at(e), "no object named '" + name + "'");
      if (!query.names(found->second)) {
        r.fail(pair.at(e), "object '" + name + "' is not in the query's group");
      }
      ends[e] = found->second;
    }
    if (ends[0] == ends[1]) r.fail(pair, "a pair needs two different objects");
    if (!query.asksPair(ends[0], ends[1])) {
      r.fail(pair, "the query does not ask this pair (named twice, or both on one side)");
    }
    const std::pair<std::size_t, std::size_t> key = std::minmax(ends[0], ends[1]);
    query.except.insert(std::lower_bound(query.except.begin(), query.except.end(), key), key);
  }
}

}  // namespace

void readQueries(const Reader& r, const Node& queries,
                 const std::map<std::string, std::size_t>& index_of, Scene& scene) {
  r.expectArray(queries);
  if (queries.value.empty()) r.fail(queries, "a scene needs at least one query");
  std::set<std::string> query_names;
  for (std::size_t i = 0; i < queries.value.size(); ++i) {
    const Node node = queries.at(i);
    r.expectObject(node, {"name", "a", "b", "among", "except", "kind", "max_pairs", "max_contacts",
                          "abs_tolerance", "rel_tolerance", "bracket_width", "frames"});
    SceneQuery query;
    std::string label;
    if (node.has("among")) {
      if (node.has("a") || node.has("b")) {
        r.fail(node, "a query names either 'a' and 'b' or 'among', not both");
      }
      query.among = readGroup(r, node.at("among"), scene, index_of);
    } else {
      readSides(r, node, scene, index_of, query, label);
    }
    if (node.has("except")) readExcept(r, node.at("except"), index_of, query);
    if (!node.has("kind")) r.fail(node, "missing 'kind'");
    query.request.kind = readQueryKind(r, node.at("kind"));
    // A group's answer is the union over its object pairs: pairs and contacts add up, a
    // boolean or a distance over a group would need a definition of its own.
    const QueryKindInfo& kind = queryKindInfo(query.request.kind);
    if (query.isGroup() && !kind.over_groups) {
      r.fail(node.at("kind"),
             "a group query ('among', or a subtree of more than one object) asks " +
                 kindNames([](const QueryKindInfo& k) { return k.over_groups; }) + " only, not " +
                 kind.name);
    }
    query.request.max_pairs =
        static_cast<std::uint64_t>(r.integer(node, "max_pairs", 0, 0, INT64_MAX));
    query.request.max_contacts =
        static_cast<std::uint64_t>(r.integer(node, "max_contacts", 0, 0, INT64_MAX));
    for (const char* key : {"abs_tolerance", "rel_tolerance"}) {
      if (!node.has(key)) continue;
      if (!kind.tolerances) {
        r.fail(node.at(key), std::string(key) + " applies to " +
                                 kindNames([](const QueryKindInfo& k) { return k.tolerances; }) +
                                 " queries only");
      }
      const double value = r.number(node.at(key));
      if (value < 0.0) r.fail(node.at(key), std::string(key) + " must be >= 0");
      (key[0] == 'a' ? query.request.abs_tolerance : query.request.rel_tolerance) = value;
    }
    readStep(r, node, kind, scene, query);
    if (node.has("frames")) query.asked = readFrameRanges(r, node.at("frames"), scene.frames);
    if (node.has("name")) {
      query.name = r.string(node.at("name"));
    } else if (label.empty()) {
      query.name =
          std::to_string(query.among.size()) + " objects " + queryKindName(query.request.kind);
    } else {
      query.name = label + " " + queryKindName(query.request.kind);
    }
    if (!query_names.insert(query.name).second) {
      r.fail(node, "duplicate query name '" + query.name + "'");
    }
    scene.queries.push_back(query);
  }
  checkQueryFrames(r, queries, scene);
}

}  // namespace collido::scene_reading
