#pragma once

#include <string>
#include <vector>

#include <collido/plugin_api.h>

namespace collido {

/// A backend linked into this program: its name and the entry function of its table.
struct StaticBackendTable {
  std::string name;          ///< the backend folder's name ("obbtree")
  CollidoPluginEntry entry;  ///< collido_plugin_table_<name>
};

/// Every backend of the build, linked statically (target collido_static_backends, generated
/// from the collido_backend() lines of the top CMakeLists.txt).
const std::vector<StaticBackendTable>& staticBackendTables();

}  // namespace collido
