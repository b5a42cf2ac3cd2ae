#include <collido/host/variant_description.h>

#include <collido/host/backend_instance.h>

namespace collido {

std::vector<VariantDescription> describeVariants(const std::shared_ptr<PluginLibrary>& plugin) {
  std::vector<VariantDescription> described;
  for (const VariantInfo& variant : plugin->variants()) {
    VariantDescription d{variant, std::nullopt, {}};
    const Result<std::unique_ptr<BackendInstance>> instance =
        BackendInstance::create(plugin, variant.name);
    if (instance.ok())
      d.capabilities = instance.value()->capabilities();
    else
      d.problem = instance.status().message();
    described.push_back(std::move(d));
  }
  return described;
}

}  // namespace collido
