// Grid axes ("A:B:N", an array of values or one number): the axes of [aeromap] and the values of
// a sweep axis (study_reader.hpp).
#include <cmath>
#include <optional>
#include <string>

#include "studies/runner/config/study_reader.hpp"

namespace orni::studies {

GridAxis readGridAxis(TableReader& r, std::string_view key, const Range& range,
                      std::string_view note) {
  const bool bounded = std::isfinite(range.lo) || std::isfinite(range.hi);
  const std::string expected = std::string("a grid spec \"A:B:N\" (") + kGridSpecMeaning +
                               "), an array of values or a number" +
                               (bounded ? ", " + range.describe("each value") : std::string()) +
                               std::string(note);
  const toml::node* n = r.take(key);
  if (!n) throw r.missingError(key, expected);
  GridAxis axis;
  if (const auto* text = n->as_string()) {
    GridSpec spec;
    std::string reason;
    if (!tryParseGridSpec(text->get(), &spec, &reason))
      throw r.valueError(key, expected, describeNode(*n) + " (" + reason + ")");
    axis = gridAxis(spec);
    for (const double v : axis.values)
      if (!range.contains(v))
        throw r.valueError(key, expected,
                           describeNode(*n) + " (value " + orni::displayNumber(v) + ")");
  } else if (const toml::array* a = n->as_array()) {
    if (a->empty()) throw r.valueError(key, expected, "an empty array");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node& e = *a->get(i);
      const std::optional<double> v = e.is_number() ? e.value<double>() : std::nullopt;
      if (!v) throw r.valueError(key, expected, describeNode(e) + " at index " + std::to_string(i));
      if (!range.contains(*v))
        throw InputError::wrongValue(
            r.fileOf(key),
            e.source().begin.line > 0 ? static_cast<int>(e.source().begin.line) : r.lineOf(key),
            r.keyPath(key), expected, sourceText(e) + " at index " + std::to_string(i));
      axis.values.push_back(*v);
    }
  } else if (n->is_number()) {
    const std::optional<double> v = n->value<double>();
    if (!v || !range.contains(*v)) throw r.valueError(key, expected, sourceText(*n));
    axis.values = {*v};
  } else {
    throw r.valueError(key, expected, describeNode(*n));
  }
  return axis;
}

void writeGridAxis(TomlWriter& out, std::string_view key, const GridAxis& axis) {
  if (axis.spec)
    out.string(key, toString(*axis.spec));
  else
    out.numberArray(key, axis.values);
}

GridAxis gridAxis(const GridSpec& spec) {
  GridAxis axis;
  axis.spec = spec;
  axis.values = gridValues(spec);
  return axis;
}

}  // namespace orni::studies
