// turf._turf: the compiled part of `import turf` (python/turf/ is the rest).
// A refused input raises turf.TurfError (python/turf/errors.py) with the
// error's name from core/errors.h, the same names turf-sim's control replies
// and refusal counters use.
#include <mujoco/mujoco.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <string>

#include "core/errors.h"
#include "python/src/scene_source.h"
#include "python/src/sim_error.h"

namespace turf::py {
void BindSsl(pybind11::module_& m);
void BindLegged(pybind11::module_& m);

namespace {

// MuJoCo's warnings go to stderr (its own handler also printed them to stdout and wrote MUJOCO_LOG.TXT into the
// caller's working directory).
void MujocoWarning(const char* message) { std::fprintf(stderr, "turf: MuJoCo warning: %s\n", message); }

// MuJoCo's fatal errors become a TurfError of the call that met one; its own handler ended the Python process (or
// waited for Enter). MuJoCo is unwound as C++ (its library has unwind tables); the world is as the error left it
// until reset() or restore() (a restore also clears the MuJoCo stack the error left marked).
[[noreturn]] void MujocoError(const char* message) {
  throw SimError(Error::kMalformed, std::string("MuJoCo: ") + message +
                                        " (the world's state is not one MuJoCo can step: reset() or restore() it)");
}

}  // namespace
}  // namespace turf::py

PYBIND11_MODULE(_turf, m) {
  namespace pyb = pybind11;
  using turf::py::SimError;
  m.doc() = "turf's simulation kernels in this process (see the turf package)";
  mju_user_warning = turf::py::MujocoWarning;
  mju_user_error = turf::py::MujocoError;
  pyb::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SimError& e) {
      const pyb::object cls = pyb::module_::import("turf.errors").attr("TurfError");
      PyErr_SetObject(cls.ptr(), pyb::make_tuple(turf::ErrorName(e.error()), e.what()).ptr());
    }
  });
  m.def("is_legged_scene", &turf::py::IsLeggedScene, pyb::arg("scene"),
        "True for a legged scene (kind: legged), False for an SSL one; a name in configs/scenes/ or a path");
  m.def("scene_path", &turf::py::ScenePath, pyb::arg("scene"));
  m.def("error_names", [] {
    std::vector<std::string> names;
    for (int e = 0; e < static_cast<int>(turf::Error::kCount); ++e)
      names.emplace_back(turf::ErrorName(static_cast<turf::Error>(e)));
    return names;
  });
  turf::py::BindSsl(m);
  turf::py::BindLegged(m);
}
