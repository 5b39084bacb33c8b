#include "synth/scene.h"

#include <array>
#include <string>

namespace floodplane::synth {

const char* shapeTypeName(const Shape& shape) {
  // In the order of the alternatives of Shape.
  static constexpr std::array<const char*, 6> names{"rectangle", "polygon", "box", "sphere", "cylinder", "prism"};
  static_assert(std::variant_size_v<Shape> == names.size());
  return names[shape.index()];
}

std::string describePrimitive(std::size_t index, std::string_view type, std::string_view name) {
  std::string text = "primitives[" + std::to_string(index) + "] (" + std::string(type);
  if (!name.empty()) {
    text += " \"" + std::string(name) + "\"";
  }
  return text + ")";
}

}  // namespace floodplane::synth
