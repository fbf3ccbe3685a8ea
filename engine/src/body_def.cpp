#include "mink/engine/body_def.hpp"

namespace mink {

std::string_view to_string(BodyType type) noexcept {
  switch (type) {
    case BodyType::static_body:
      return "static";
    case BodyType::kinematic:
      return "kinematic";
    case BodyType::dynamic:
      return "dynamic";
  }
  return "static";
}

}  // namespace mink
