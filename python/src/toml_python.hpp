// Python objects <-> TOML nodes, and dotted file keys ("tail.arm_m", "wing.members[2].diameter_m")
// inside a TOML document: how the Python module reads and writes a vehicle's or a study's fields by
// the names of the files.
#pragma once

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

#include <string>
#include <variant>
#include <vector>

namespace orni::python {

/// A TOML value of a Python object: bool, int, float, str, a sequence (list, tuple, 1-D NumPy
/// array) -> array, a dict with str keys -> table. Anything else: TypeError naming `key`.
toml::table toTomlTable(const pybind11::dict& d, const std::string& key);
void insertValue(toml::table& t, const std::string& name, const pybind11::handle& value,
                 const std::string& key);

/// The Python object of a TOML node (tables as dicts, arrays as lists).
pybind11::object toPython(const toml::node& node);

/// One step of a dotted key: a table member or an array index.
using KeyStep = std::variant<std::string, std::size_t>;
/// "wing.members[2].diameter_m" -> {"wing", "members", 2, "diameter_m"}; KeyError when malformed.
std::vector<KeyStep> parseDottedKey(const std::string& key);

/// The node at `key` in `root`, or null.
const toml::node* findNode(const toml::table& root, const std::vector<KeyStep>& steps);

/// Sets the node at `key` in `root` to `value`, creating missing tables on the way (the reader then
/// names an unknown key as such). KeyError when an array index is out of range or a step goes
/// through a value that is not a table or array.
void setNode(toml::table& root, const std::vector<KeyStep>& steps, const std::string& key,
             const pybind11::handle& value);

/// Every leaf key of `root` in document order ("air.density_kgpm3", "wing.members[0].kind", ...).
std::vector<std::string> leafKeys(const toml::table& root);

}  // namespace orni::python
