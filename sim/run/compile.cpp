#include "sim/run/compile.h"

#include "sim/run/navigation.h"

namespace vascsim {

std::shared_ptr<const Model> compile(const Scene& input) {
  Scene scene = input;
  std::shared_ptr<Navigation> navigation;
  if (scene.has_environment) navigation = prepare_navigation(scene);
  auto model = std::make_shared<Model>(build_model(scene));
  if (navigation) add_navigation_modules(scene, *navigation, *model);
  model->scene = std::move(scene);
  model->navigation = std::move(navigation);
  return model;
}

}  // namespace vascsim
