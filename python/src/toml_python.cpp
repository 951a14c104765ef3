#include "toml_python.hpp"

#include <pybind11/numpy.h>

#include <cctype>
#include <utility>

namespace py = pybind11;

namespace orni::python {

namespace {

py::type_error notAValue(const std::string& key, const py::handle& value) {
  return py::type_error("key '" + key + "': expected a bool, int, float, str, list or dict, got " +
                        std::string(py::str(py::type::of(value).attr("__name__"))));
}

template <typename Container>
void appendValue(Container& out, const py::handle& value, const std::string& key) {
  // bool before int: a Python bool is an int.
  if (py::isinstance<py::bool_>(value)) {
    out.push_back(value.cast<bool>());
  } else if (py::isinstance<py::int_>(value)) {
    out.push_back(value.cast<std::int64_t>());
  } else if (py::isinstance<py::float_>(value) || py::isinstance(value, py::module_::import("numpy").attr("floating"))) {
    out.push_back(value.cast<double>());
  } else if (py::isinstance(value, py::module_::import("numpy").attr("integer"))) {
    out.push_back(value.cast<std::int64_t>());
  } else if (py::isinstance<py::str>(value)) {
    out.push_back(value.cast<std::string>());
  } else if (py::isinstance<py::dict>(value)) {
    out.push_back(toTomlTable(value.cast<py::dict>(), key));
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
             py::isinstance<py::array>(value)) {
    toml::array a;
    std::size_t i = 0;
    for (const py::handle item : value)
      appendValue(a, item, key + "[" + std::to_string(i++) + "]");
    out.push_back(std::move(a));
  } else {
    throw notAValue(key, value);
  }
}

// A one-element holder so that appendValue serves tables and arrays alike.
struct Single {
  toml::array a;
  template <typename T>
  void push_back(T&& v) {
    a.push_back(std::forward<T>(v));
  }
};

}  // namespace

void insertValue(toml::table& t, const std::string& name, const py::handle& value,
                 const std::string& key) {
  Single one;
  appendValue(one, value, key);
  t.insert_or_assign(name, std::move(*one.a.get(0)));
}

toml::table toTomlTable(const py::dict& d, const std::string& key) {
  toml::table t;
  for (const auto& [k, v] : d) {
    if (!py::isinstance<py::str>(k)) throw py::type_error("key '" + key + "': table keys are str");
    const std::string name = k.cast<std::string>();
    insertValue(t, name, v, key.empty() ? name : key + "." + name);
  }
  return t;
}

py::object toPython(const toml::node& node) {
  if (const auto* t = node.as_table()) {
    py::dict d;
    for (const auto& [k, v] : *t) d[py::str(std::string(k.str()))] = toPython(v);
    return std::move(d);
  }
  if (const auto* a = node.as_array()) {
    py::list l;
    for (const auto& v : *a) l.append(toPython(v));
    return std::move(l);
  }
  if (const auto* v = node.as_boolean()) return py::bool_(v->get());
  if (const auto* v = node.as_integer()) return py::int_(v->get());
  if (const auto* v = node.as_floating_point()) return py::float_(v->get());
  if (const auto* v = node.as_string()) return py::str(v->get());
  return py::none();
}

std::vector<KeyStep> parseDottedKey(const std::string& key) {
  std::vector<KeyStep> steps;
  std::size_t i = 0;
  auto bad = [&]() { return py::key_error("malformed key '" + key + "'"); };
  while (i < key.size()) {
    std::size_t j = i;
    while (j < key.size() && key[j] != '.' && key[j] != '[') ++j;
    if (j == i) throw bad();
    steps.emplace_back(key.substr(i, j - i));
    while (j < key.size() && key[j] == '[') {
      std::size_t k = j + 1;
      while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) ++k;
      if (k == j + 1 || k >= key.size() || key[k] != ']') throw bad();
      steps.emplace_back(static_cast<std::size_t>(std::stoul(key.substr(j + 1, k - j - 1))));
      j = k + 1;
    }
    if (j < key.size()) {
      if (key[j] != '.' || j + 1 == key.size()) throw bad();
      ++j;
    }
    i = j;
  }
  if (steps.empty()) throw bad();
  return steps;
}

const toml::node* findNode(const toml::table& root, const std::vector<KeyStep>& steps) {
  const toml::node* n = &root;
  for (const KeyStep& s : steps) {
    if (const auto* name = std::get_if<std::string>(&s)) {
      const auto* t = n->as_table();
      n = t ? t->get(*name) : nullptr;
    } else {
      const auto* a = n->as_array();
      n = a ? a->get(std::get<std::size_t>(s)) : nullptr;
    }
    if (!n) return nullptr;
  }
  return n;
}

void setNode(toml::table& root, const std::vector<KeyStep>& steps, const std::string& key,
             const py::handle& value) {
  toml::node* n = &root;
  for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
    if (const auto* name = std::get_if<std::string>(&steps[i])) {
      auto* t = n->as_table();
      if (!t) throw py::key_error("key '" + key + "': '" + *name + "' is not inside a table");
      if (!t->contains(*name)) t->insert(*name, toml::table{});
      n = t->get(*name);
    } else {
      auto* a = n->as_array();
      const std::size_t index = std::get<std::size_t>(steps[i]);
      if (!a || index >= a->size())
        throw py::key_error("key '" + key + "': no element " + std::to_string(index));
      n = a->get(index);
    }
  }
  Single one;
  appendValue(one, value, key);
  if (const auto* name = std::get_if<std::string>(&steps.back())) {
    auto* t = n->as_table();
    if (!t) throw py::key_error("key '" + key + "': '" + *name + "' is not inside a table");
    t->insert_or_assign(*name, std::move(*one.a.get(0)));
  } else {
    auto* a = n->as_array();
    const std::size_t index = std::get<std::size_t>(steps.back());
    if (!a || index >= a->size())
      throw py::key_error("key '" + key + "': no element " + std::to_string(index));
    a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(index), std::move(*one.a.get(0)));
  }
}

namespace {

void collectLeaves(const toml::node& n, const std::string& prefix, std::vector<std::string>& out) {
  if (const auto* t = n.as_table()) {
    for (const auto& [k, v] : *t)
      collectLeaves(v, prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str()),
                    out);
  } else if (const auto* a = n.as_array(); a && !a->empty() && a->get(0)->is_table()) {
    for (std::size_t i = 0; i < a->size(); ++i)
      collectLeaves(*a->get(i), prefix + "[" + std::to_string(i) + "]", out);
  } else {
    out.push_back(prefix);
  }
}

}  // namespace

std::vector<std::string> leafKeys(const toml::table& root) {
  std::vector<std::string> out;
  collectLeaves(root, std::string(), out);
  return out;
}

}  // namespace orni::python
