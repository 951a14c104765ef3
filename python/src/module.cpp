// ornithopter._ornithopter: the compiled half of the Python module `ornithopter`
// (python/ornithopter/__init__.py is the public face: docstrings, defaults, NumPy results).
// Everything here calls the code of the command line: the same readers (study_file, vehicle_file),
// the same runs (runStudy) and the same summaries, so results equal summary.json to the last bit.
// Every computation releases the GIL and can be interrupted by Ctrl-C (interruptible.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/model/invalid_model_error.hpp"
#include "core/version.hpp"
#include "studies/runner/commands/run_study.hpp"
#include "studies/runner/commands/simulate_command.hpp"
#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/study_reader.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/output/console.hpp"
#include "studies/runner/output/folder_lock.hpp"
#include "studies/runner/plotting/gnuplot.hpp"
#include "interruptible.hpp"
#include "tethered_run.hpp"
#include "toml_python.hpp"
#include "vehicle_object.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;
using orni::python::VehicleObject;
using orni::studies::Study;

namespace {

/// ornithopter.InputError (a ValueError) with .file, .line, .key, .expected.
PyObject* g_input_error = nullptr;

void raiseInputError(const std::string& what, const std::string& file, int line,
                     const std::string& key, const std::string& expected) {
  py::object type = py::reinterpret_borrow<py::object>(g_input_error);
  py::object e = type(what);
  e.attr("file") = file;
  e.attr("line") = line;
  e.attr("key") = key;
  e.attr("expected") = expected;
  PyErr_SetObject(g_input_error, e.ptr());
}

/// A study of `kind` on `vehicle` with the analysis section `section` (a dict in the file's key
/// names and units), read by the study-file reader like a file with an inline [vehicle]. Errors
/// name the file "<python>" and the key ("trim.max_iterations").
Study makeStudy(const VehicleObject& vehicle, const std::string& kind, const std::string& name,
                const py::dict& section) {
  toml::table root;
  root.insert("kind", kind);
  root.insert("name", name);
  root.insert("vehicle", vehicle.document());
  if (!vehicle.source().empty()) root.insert("vehicle_source", vehicle.source());
  if (!section.empty()) root.insert(kind, orni::python::toTomlTable(section, kind));
  return orni::studies::readStudyRoot(root, "<python>");
}

/// The CLI's `run` of a study (every analysis but the tethered simulate goes through it),
/// interruptible by Ctrl-C (interruptible.hpp).
int runStudyInto(const Study& study, const std::string& out_dir, int threads, bool figures) {
  return orni::python::interruptible([&] {
    orni::studies::setFiguresWanted(figures);  // process-wide: each call says what it wants
    return orni::studies::runStudyLocked(study, out_dir, threads);
  });
}

}  // namespace

PYBIND11_MODULE(_ornithopter, m) {
  m.doc() = "Compiled core of the ornithopter package (use the package `ornithopter`).";
  // A library call is silent: the runner's result lines, notes and progress are not printed
  // (the returned summary holds them); figures only when asked (run_study's `figures`).
  orni::studies::setConsoleQuiet(true);
  orni::studies::setConsoleCapture(true);  // ... kept for Python's logging (console_logging.hpp)
  orni::studies::setFiguresWanted(false);
  m.attr("__version__") = orni::kVersion;
  m.attr("git_revision") = orni::kGitRevision;

  g_input_error = PyErr_NewExceptionWithDoc(
      "ornithopter.InputError",
      "Bad input (a file, a key, a value): the CLI's exit status 2.\n\n"
      "Attributes: file (str: the file, or '<python>' for values given from Python), line (int, "
      "0 when no line applies), key (str: the dotted key, e.g. 'tail.arm_m'), expected (str: "
      "what the key expects, '' when the message says it otherwise).",
      PyExc_ValueError, nullptr);
  m.attr("InputError") = py::handle(g_input_error);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const orni::studies::InputError& e) {
      raiseInputError(e.what(), e.file(), e.line(), e.key(), e.expected());
    } catch (const orni::InvalidModelError& e) {
      raiseInputError(std::string("invalid model: ") + e.what(), "<python>", 0, "", "");
    } catch (const orni::studies::FolderBusyError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const orni::Cancelled& e) {  // another call's Ctrl-C (the request is process-wide)
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });

  py::class_<VehicleObject>(m, "Vehicle")
      // Vehicle(path) reads a file, Vehicle(dict) a vehicle document (from_dict).
      .def(py::init([](const py::object& what) {
             if (py::isinstance<py::dict>(what))
               return VehicleObject::fromDict(what.cast<py::dict>(), "");
             const std::string path =
                 py::module_::import("os").attr("fspath")(what).cast<std::string>();
             if (!py::module_::import("os.path").attr("isfile")(path).cast<bool>()) {
               const py::object e = py::module_::import("builtins")
                                        .attr("FileNotFoundError")(ENOENT, std::strerror(ENOENT), path);
               PyErr_SetObject(PyExc_FileNotFoundError, e.ptr());
               throw py::error_already_set();
             }
             return VehicleObject::load(path);
           }),
           py::arg("source"))
      .def_static("load", &VehicleObject::load, py::arg("path"))
      .def("__getitem__", &VehicleObject::get)
      .def("__setitem__", &VehicleObject::set)
      .def("__contains__", &VehicleObject::contains)
      .def("keys", &VehicleObject::keys)
      .def("to_toml", &VehicleObject::toToml)
      .def_static("from_dict", &VehicleObject::fromDict, py::arg("d"), py::arg("source") = "")
      .def_static("from_toml", &VehicleObject::fromToml, py::arg("text"), py::arg("source") = "")
      .def("to_dict", &VehicleObject::toDict)
      .def("items", &VehicleObject::items)
      .def("__len__", &VehicleObject::size)
      .def("__repr__", &VehicleObject::repr)
      .def("__eq__", [](const VehicleObject& a, const py::object& b) -> py::object {
        if (!py::isinstance<VehicleObject>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(a.toToml() == b.cast<const VehicleObject&>().toToml());
      })
      .def("__copy__", &VehicleObject::clone)
      .def("__deepcopy__", [](const VehicleObject& v, const py::dict&) { return v.clone(); },
           py::arg("memo"))
      .def(py::pickle(
          [](const VehicleObject& v) { return py::make_tuple(v.toToml(), v.source()); },
          [](const py::tuple& t) {
            if (t.size() != 2) throw std::runtime_error("Vehicle: a pickle state of 2 items expected");
            return VehicleObject::fromToml(t[0].cast<std::string>(), t[1].cast<std::string>());
          }))
      .def_property_readonly("name", [](const VehicleObject& v) { return v.model().name; })
      .def_property_readonly("source", &VehicleObject::source);

  py::class_<Study>(m, "Study")
      .def_property_readonly("kind",
                             [](const Study& s) { return std::string(orni::studies::toString(s.kind)); })
      .def_property_readonly("name", [](const Study& s) { return s.name; })
      .def_property_readonly("path", [](const Study& s) { return s.study_path.string(); })
      .def("resolved_toml", &orni::studies::resolvedStudyToml);

  m.def("load_study", [](const std::string& path) { return orni::studies::loadStudyFile(path); },
        py::arg("path"));
  m.def("make_study", &makeStudy, py::arg("vehicle"), py::arg("kind"), py::arg("name"),
        py::arg("section"));
  m.def("run_study", &runStudyInto, py::arg("study"), py::arg("out_dir"), py::arg("threads"),
        py::arg("figures") = false);
  m.def(
      "run_stability",
      [](const VehicleObject& vehicle, const std::string& name, const py::dict& section,
         const std::string& out_dir, bool figures) {
        const Study study = orni::studies::stabilityStudy(makeStudy(vehicle, "trim", name, section));
        return orni::python::interruptible([&] {
          orni::studies::setFiguresWanted(figures);
          return orni::studies::runStabilityLocked(study, out_dir);
        });
      },
      py::arg("vehicle"), py::arg("name"), py::arg("section"), py::arg("out_dir"),
      py::arg("figures") = false);
  m.def("simulate_tethered", &orni::python::simulateTetheredStudy, py::arg("vehicle"),
        py::arg("study"), py::arg("histories"));
  m.def("history_columns", []() {
    py::list names;
    for (const auto& c : orni::studies::historyColumns()) names.append(py::make_tuple(c.name, c.unit));
    return names;
  });
  m.def("study_settings", [](const Study& s) {
    py::dict d;
    d["mode"] = s.simulate().options.mode == orni::FlightMode::kFree ? "free" : "tethered";
    d["at_trim"] = s.simulate().at_trim;
    d["history_every"] = s.simulate().history_every;
    return d;
  });
}
