// The engine's errors as Python exceptions: minkowski.Error and one subclass per C++ type,
// each carrying the engine's message (and the offending point's index, or the scene file's
// JSON path, where the C++ error has one).
#include "bindings.hpp"
#include "mink/byte_stream.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/stale_id_error.hpp"
#include "mink/error.hpp"
#include "mink/render/render_error.hpp"

namespace mink::python {

namespace {

// The classes live as long as the module; they are never freed (the interpreter may be
// finalising when a static py::object would be destroyed).
struct ErrorClasses {
  PyObject* error = nullptr;
  PyObject* invalid_argument = nullptr;
  PyObject* scene_file = nullptr;
  PyObject* non_finite_input = nullptr;
  PyObject* degenerate_input = nullptr;
  PyObject* stale_id = nullptr;
  PyObject* output = nullptr;
  PyObject* gl_context = nullptr;
  PyObject* snapshot = nullptr;
};
ErrorClasses classes;

PyObject* new_class(py::module_& m, const char* name, const char* doc, py::tuple bases) {
  const std::string qualified = "minkowski." + std::string(name);
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

py::handle builtin(const char* name) {
  return py::object(py::module_::import("builtins").attr(name)).release();
}

// Raises `type` with the message, after setting `attribute` on the instance when given.
void raise(PyObject* type, const char* message, const char* attribute = nullptr,
           py::object value = {}) {
  py::object instance = py::reinterpret_borrow<py::object>(type)(message);
  if (attribute != nullptr) instance.attr(attribute) = value;
  PyErr_SetObject(type, instance.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  const py::handle runtime_error = builtin("RuntimeError");
  const py::handle value_error = builtin("ValueError");
  classes.error = new_class(m, "Error",
                            "Root of every error the engine raises (mink::Error); the message is "
                            "the engine's.",
                            py::make_tuple(runtime_error));
  const py::handle error(classes.error);
  classes.invalid_argument = new_class(
      m, "InvalidArgumentError", "A parameter outside its documented domain; the message names it.",
      py::make_tuple(error, value_error));
  classes.scene_file =
      new_class(m, "SceneFileError",
                "A scene file that cannot be used; json_path names the offending value "
                "(e.g. 'bodies[3].shapes[0].points[2]').",
                py::make_tuple(py::handle(classes.invalid_argument)));
  classes.non_finite_input =
      new_class(m, "NonFiniteInputError",
                "A coordinate that is NaN or infinite; index names the offending point.",
                py::make_tuple(error, value_error));
  classes.degenerate_input =
      new_class(m, "DegenerateInputError",
                "A point set with no area: fewer than three distinct, non-collinear points.",
                py::make_tuple(error, value_error));
  classes.stale_id =
      new_class(m, "StaleIdError",
                "A body, shape or joint used after it was destroyed, or from another world.",
                py::make_tuple(error, builtin("LookupError")));
  classes.output =
      new_class(m, "OutputError",
                "An output could not be written (a file, a directory, ffmpeg): the environment "
                "failed, not the input. The message names the path.",
                py::make_tuple(error, builtin("OSError")));
  classes.gl_context = new_class(
      m, "GlContextError",
      "A GL context could not be made or a GL call failed; the message names the backend.",
      py::make_tuple(error));
  classes.snapshot = new_class(
      m, "SnapshotError",
      "A snapshot (or pickled World) that cannot be restored: another format version or build, "
      "truncated or corrupt. The message says which; the world is left as it was.",
      py::make_tuple(error, value_error));

  // Most derived first: a SceneFileError is also an InvalidArgumentError.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const SceneFileError& e) {
      raise(classes.scene_file, e.what(), "json_path", py::str(e.json_path()));
    } catch (const InvalidArgumentError& e) {
      raise(classes.invalid_argument, e.what());
    } catch (const NonFiniteInputError& e) {
      raise(classes.non_finite_input, e.what(), "index", py::int_(e.index()));
    } catch (const DegenerateInputError& e) {
      raise(classes.degenerate_input, e.what());
    } catch (const StaleIdError& e) {
      raise(classes.stale_id, e.what());
    } catch (const OutputError& e) {
      raise(classes.output, e.what());
    } catch (const GlContextError& e) {
      raise(classes.gl_context, e.what());
    } catch (const SnapshotError& e) {
      raise(classes.snapshot, e.what());
    } catch (const Error& e) {
      raise(classes.error, e.what());
    }
  });
}

}  // namespace mink::python
