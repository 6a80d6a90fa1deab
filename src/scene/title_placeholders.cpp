#include "scene/title_placeholders.hpp"

#include <cstdio>
#include <utility>
#include <vector>

namespace sl {

namespace {

// 3 as "3", 3.2 as "3.2", as a person writes L.
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace

std::string fillTitlePlaceholders(const std::string& title, const Scene& scene,
                                  std::optional<double> injectivityRadius) {
  std::vector<std::pair<std::string, std::string>> values{
      {"{L}", shortNumber(scene.chain.baseLength)},
      {"{n}", std::to_string(scene.chain.rods)},
      {"{name}", scene.name},
  };
  if (!scene.runs.empty()) {
    values.push_back({"{method}", std::string(nameOf(scene.runs.front().config.method))});
    values.push_back({"{integrator}", std::string(nameOf(scene.runs.front().config.integrator))});
  }
  // A family's number of members; a found motion's length and stability, once the commands have resolved it.
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    const std::string run = "{runs[" + std::to_string(i) + "].";
    if (scene.runs[i].family) values.push_back({run + "family.count}", std::to_string(scene.runs[i].family->count)});
    const std::optional<FoundMotion>& motion = scene.runs[i].initial.motion;
    if (!motion) continue;
    char length[32];
    std::snprintf(length, sizeof length, "%.4f", motion->length);
    values.push_back({run + "length}", length});
    if (motion->stability) values.push_back({run + "stability}", nameOf(*motion->stability)});
  }
  if (injectivityRadius) {
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.4f", *injectivityRadius);
    values.push_back({"{injectivity_radius}", radius});
  }
  std::string text;
  for (std::size_t i = 0; i < title.size();) {
    bool replaced = false;
    for (const auto& [placeholder, value] : values)
      if (title.compare(i, placeholder.size(), placeholder) == 0) {
        text += value;
        i += placeholder.size();
        replaced = true;
        break;
      }
    if (!replaced) text += title[i++];
  }
  return text;
}

}  // namespace sl
