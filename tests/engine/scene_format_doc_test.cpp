#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

#include "mink/engine/scene_fields.hpp"

// docs/scene-format.md carries one field table per scene-file object between
// "<!-- fields: NAME -->" and "<!-- end fields -->". Each must be exactly what the engine's
// table renders, so the docs can neither miss a field nor state a wrong default or range.

namespace mink {
namespace {

std::string number(Real x) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

std::string vec2(const Vec2& v) {
  return "[" + number(v.x()) + ", " + number(v.y()) + "]";
}

template <class Object>
std::string names(const SceneField<Object>& field) {
  std::string out;
  for (const std::string_view name : field.names()) {
    out += (out.empty() ? "`\"" : ", `\"") + std::string(name) + "\"`";
  }
  return out;
}

template <class Object>
std::string kind_text(const SceneField<Object>& field) {
  switch (field.kind) {
    case FieldKind::real:
      return "number";
    case FieldKind::integer:
      return "integer";
    case FieldKind::boolean:
      return "true or false";
    case FieldKind::vec2:
      return "[x, y]";
    case FieldKind::points:
      return "[[x, y], ...]";
    case FieldKind::bits:
      return "integer or hex string";
    case FieldKind::user_data:
      return "integer >= 0";
    case FieldKind::name:
      return names(field);
  }
  return "?";
}

template <class Object>
std::string value_text(const SceneField<Object>& field, const FieldValue& value) {
  switch (field.kind) {
    case FieldKind::real:
      return number(std::get<Real>(value));
    case FieldKind::integer:
      return std::to_string(std::get<std::int64_t>(value));
    case FieldKind::boolean:
      return std::get<bool>(value) ? "true" : "false";
    case FieldKind::vec2:
      return vec2(std::get<Vec2>(value));
    case FieldKind::points:
      return std::get<std::vector<Vec2>>(value).empty() ? "[]" : "?";
    case FieldKind::bits: {
      char buffer[20];
      const auto end =
          std::to_chars(buffer, buffer + sizeof buffer, std::get<std::uint64_t>(value), 16).ptr;
      std::string hex(buffer, end);
      for (char& c : hex) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return "`\"0x" + hex + "\"`";
    }
    case FieldKind::user_data:
      return std::to_string(std::get<std::uint64_t>(value));
    case FieldKind::name:
      return "`\"" + std::get<std::string>(value) + "\"`";
  }
  return "?";
}

template <class Object>
std::string default_text(const SceneField<Object>& field) {
  if (field.required) return "required";
  if (field.present != nullptr) return "none";
  return value_text(field, field.get(Object{}));
}

// A joint key's default depends on the kind: the value in each kind's default definition that
// has the key, one value when they agree, else "kind, kind: value; kind: value". A nested
// part's keys default to what they are once the part's object is given (`part`).
std::string default_text(const SceneField<SceneJointRecord>& field,
                         const SceneJointPart* part = nullptr) {
  if (field.required) return "required";
  if (field.present != nullptr) return "none";
  const SceneField<SceneJointRecord>& type = joint_fields()[0];
  std::vector<std::pair<std::string, std::string>> values;  // value, kinds
  for (const std::string_view name : type.names()) {
    SceneJointRecord record;
    type.set(record, std::string(name));
    if (part != nullptr) {
      if (!part->applies(record)) continue;
      part->enable(record);
    }
    if (field.applies != nullptr && !field.applies(record)) continue;
    const std::string value = value_text(field, field.get(record));
    auto same =
        std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == value; });
    if (same == values.end()) {
      values.emplace_back(value, std::string(name));
    } else {
      same->second += ", " + std::string(name);
    }
  }
  if (values.size() == 1) return values[0].first;
  std::string out;
  for (const auto& [value, kinds] : values) out += (out.empty() ? "" : "; ") + kinds + ": " + value;
  return out;
}

template <class Object, class... Context>
std::string render(std::span<const SceneField<Object>> fields, Context... context) {
  std::string out =
      "| key | value | default | allowed | meaning |\n"
      "|-----|-------|---------|---------|---------|\n";
  for (const SceneField<Object>& field : fields) {
    std::string meaning(field.doc);
    if (field.applies != nullptr) meaning += " (only on " + std::string(field.applies_to) + ")";
    out += "| `" + std::string(field.key) + "` | " + kind_text(field) + " | " +
           default_text(field, context...) + " | " + field.range.describe() + " | " + meaning +
           " |\n";
  }
  return out;
}

std::string read_docs() {
  std::ifstream in(MINK_DOCS_DIR "/scene-format.md");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between the table's markers, or a note that they are missing.
std::string documented(const std::string& docs, const std::string& name) {
  const std::string begin = "<!-- fields: " + name + " -->\n";
  const std::size_t start = docs.find(begin);
  if (start == std::string::npos) return "(no " + begin + " marker)";
  const std::size_t body = start + begin.size();
  const std::size_t end = docs.find("<!-- end fields -->", body);
  if (end == std::string::npos) return "(no end marker after " + name + ")";
  return docs.substr(body, end - body);
}

TEST(SceneFormatDoc, EveryFieldTableIsDocumentedAsTheEngineHasIt) {
  const std::string docs = read_docs();
  ASSERT_FALSE(docs.empty()) << "cannot read " MINK_DOCS_DIR "/scene-format.md";
  const auto expect_table = [&](const std::string& name, const std::string& table) {
    EXPECT_EQ(documented(docs, name), table) << "docs/scene-format.md, table " << name
                                             << " should read:\n<!-- fields: " << name << " -->\n"
                                             << table << "<!-- end fields -->";
  };
  expect_table("world", render(world_fields()));
  expect_table("body", render(body_fields()));
  expect_table("shape", render(shape_fields()));
  expect_table("filter", render(filter_fields()));
  expect_table("scale", render(scale_fields()));
  for (const SceneShapeForm& form : shape_forms()) {
    expect_table(std::string(form.key), render(form.fields));
  }
  expect_table("box", render(box_fields()));
  expect_table("polygon", render(regular_polygon_fields()));
  expect_table("joint", render(joint_fields()));
  for (const SceneJointPart& part : joint_parts()) {
    expect_table(std::string(part.key), render(part.fields, &part));
  }
}

}  // namespace
}  // namespace mink
