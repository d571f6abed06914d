#include "body/body_visual.hpp"

namespace crux {

const char* visual_shape_name(VisualShape shape) {
  switch (shape) {
    case VisualShape::Box:
      return "box";
    case VisualShape::Cylinder:
      return "cylinder";
    case VisualShape::Sphere:
      return "sphere";
  }
  return "sphere";
}

}  // namespace crux
