#include "names.hpp"

#include <initializer_list>
#include <string>

#include "mink/error.hpp"

namespace mink::python {

namespace {

// The value whose to_string is `name`, or an error listing every name.
template <class Enum>
Enum parse_name(std::string_view name, std::initializer_list<Enum> values, const char* what) {
  std::string list;
  for (const Enum value : values) {
    if (to_string(value) == name) return value;
    list += (list.empty() ? "'" : ", '") + std::string(to_string(value)) + "'";
  }
  throw InvalidArgumentError(std::string(what) + " '" + std::string(name) + "' is not one of " +
                             list);
}

}  // namespace

BodyType parse_body_type(std::string_view name) {
  return parse_name(name, {BodyType::static_body, BodyType::kinematic, BodyType::dynamic},
                    "body type");
}

ShapeType parse_shape_type(std::string_view name) {
  return parse_name(name,
                    {ShapeType::polygon, ShapeType::circle, ShapeType::capsule, ShapeType::segment,
                     ShapeType::chain},
                    "shape type");
}

}  // namespace mink::python
