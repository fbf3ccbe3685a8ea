#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "mink/engine/body_def.hpp"
#include "mink/engine/filter.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/engine/world_def.hpp"

namespace mink {

/// @file
/// @brief The fields of each scene-file object, one table per object (docs/scene-format.md).
/// The reader, the writer, validation, the round-trip test and the format's documentation all
/// walk these tables, so a field is added in exactly one place.

/// @brief How a field is spelled in JSON, and which FieldValue alternative holds it.
enum class FieldKind : std::uint8_t {
  real,       ///< a finite number; Real
  integer,    ///< a JSON integer; std::int64_t
  boolean,    ///< true or false; bool
  vec2,       ///< [x, y]; Vec2
  points,     ///< [[x, y], ...]; std::vector<Vec2>
  bits,       ///< 64 bits: an integer 0..2^64-1 or a hex string "0x..."; std::uint64_t
  user_data,  ///< an integer 0..2^64-1; std::uint64_t
  name,       ///< one of SceneField::names; std::string
};

/// @brief A field's value, whatever its kind (see FieldKind for which alternative).
using FieldValue =
    std::variant<Real, std::int64_t, bool, Vec2, std::vector<Vec2>, std::uint64_t, std::string>;

/// @brief The numbers a real, integer, vec2 or points field accepts (each coordinate).
struct FieldRange {
  Real min = -std::numeric_limits<Real>::infinity();  ///< lowest allowed
  Real max = std::numeric_limits<Real>::infinity();   ///< highest allowed
  bool min_exclusive = false;                         ///< true: `min` itself is refused

  /// @brief True when `value` lies in the range.
  bool contains(Real value) const noexcept;
  /// @brief The range as the docs and error messages say it: "> 0", ">= 0", "1..1000", "" for
  /// any finite number.
  std::string describe() const;
};

/// One key of a scene-file object whose C++ twin is `Object`.
template <class Object>
struct SceneField {
  std::string_view key;                               ///< the JSON key
  FieldKind kind = FieldKind::real;                   ///< its JSON form and FieldValue alternative
  FieldValue (*get)(const Object&) = nullptr;         ///< reads the field from an object
  void (*set)(Object&, const FieldValue&) = nullptr;  ///< writes a checked value into an object
  std::string_view doc;                               ///< what it means, for docs/scene-format.md
  FieldRange range{};     ///< allowed numbers (real, integer, vec2, points)
  bool required = false;  ///< a missing key is an error (no default then)
  /// FieldKind::name: the accepted names, in the order the docs list them.
  std::span<const std::string_view> (*names)() = nullptr;
  /// Null for a field every object has; otherwise the field belongs only to objects for which
  /// this returns true: elsewhere the reader refuses it and the writer leaves it out.
  bool (*applies)(const Object&) = nullptr;
  std::string_view applies_to;  ///< which objects `applies` accepts, e.g. "polygon shapes"
  /// Null for a key that always has a value. Otherwise an optional key, absent by default
  /// (the docs say "none"): the writer writes it only where this returns true, and reading
  /// it turns on what it sets (a joint limit, a break threshold); never true for a read-only
  /// key.
  bool (*present)(const Object&) = nullptr;
};

/// @brief A shape's geometry written as one nested object (`"circle": {...}`): the key, the
/// ShapeType it makes and the fields of the nested object.
struct SceneShapeForm {
  std::string_view key;                          ///< "circle", "capsule", "segment", "chain"
  ShapeType type = ShapeType::polygon;           ///< the kind of shape it makes
  std::span<const SceneField<ShapeDef>> fields;  ///< the nested object's keys
};

/// @brief The arguments of the scene file's `box` helper (ShapeDef::box); read, never written.
struct SceneBox {
  Vec2 half_extents{0, 0};  ///< positive
  Vec2 center{0, 0};        ///< body-local
  Real angle = 0;           ///< radians
};

/// @brief The arguments of the `polygon` helper (ShapeDef::regular_polygon); read, never written.
struct SceneRegularPolygon {
  std::int64_t count = 0;  ///< vertex count, >= 3
  Real radius = 0;         ///< circumradius, > 0
  Vec2 center{0, 0};       ///< body-local
};

/// A `joints` entry as its table reads and writes it: the scene's joint (body-local), and the
/// read-only world-frame keys, which the reader turns into the joint's body-local anchors and
/// axis with the bodies' defined poses once every key is read.
struct SceneJointRecord {
  SceneJoint joint;              ///< what the entry makes
  std::optional<Vec2> anchor;    ///< "anchor": world point on both bodies
  std::optional<Vec2> anchor_a;  ///< "anchor_a": world point on body A
  std::optional<Vec2> anchor_b;  ///< "anchor_b": world point on body B
  std::optional<Vec2> axis;      ///< "axis": world direction, any length but 0
};

/// A joint's setting written as one nested object (`"motor": {...}`), on the kinds that have
/// it; giving the object turns the setting on unless it says `"enabled": false`.
struct SceneJointPart {
  std::string_view key;                                  ///< "motor", "spring"
  bool (*applies)(const SceneJointRecord&) = nullptr;    ///< the kinds that have it
  std::string_view applies_to;                           ///< those kinds, for messages
  void (*enable)(SceneJointRecord&) = nullptr;           ///< what giving the object does
  std::span<const SceneField<SceneJointRecord>> fields;  ///< the nested object's keys
};

/// @brief The `world` object: every WorldDef setting.
std::span<const SceneField<WorldDef>> world_fields() noexcept;
/// @brief A body's keys (BodyDef) other than `shapes`.
std::span<const SceneField<BodyDef>> body_fields() noexcept;
/// @brief A shape's keys (ShapeDef) other than its geometry form, `filter` and `scale`. The
/// polygon form `points` is one of them (it applies to polygon shapes only).
std::span<const SceneField<ShapeDef>> shape_fields() noexcept;
/// @brief A shape's `filter` object.
std::span<const SceneField<Filter>> filter_fields() noexcept;
/// @brief A polygon shape's `scale` object.
std::span<const SceneField<ShapeScale>> scale_fields() noexcept;
/// @brief The nested geometry objects the writer writes: circle, capsule, segment, chain.
std::span<const SceneShapeForm> shape_forms() noexcept;
/// @brief A joint's keys other than its nested parts (`type` first: the others depend on it).
std::span<const SceneField<SceneJointRecord>> joint_fields() noexcept;
/// @brief A joint's nested objects: motor, spring.
std::span<const SceneJointPart> joint_parts() noexcept;
/// @brief The `box` helper's object.
std::span<const SceneField<SceneBox>> box_fields() noexcept;
/// @brief The `polygon` helper's object.
std::span<const SceneField<SceneRegularPolygon>> regular_polygon_fields() noexcept;

}  // namespace mink
