// `ornithopter keys [GROUP] [--markdown]`: the field table (core/model/field_table.hpp) printed,
// every input key with its unit, type and range, default and meaning. The key reference docs/keys.md
// is the Markdown form of it (tests/regression/readme_keys.sh compares them).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace orni::studies {

/// The table of every key of `group` (a FieldSpec::group(), e.g. "vehicle", "trim"; empty = every
/// group) as aligned plain text or, with `markdown`, as one Markdown table per group. nullopt for
/// an unknown group.
std::optional<std::string> keysText(std::string_view group, bool markdown);

}  // namespace orni::studies
