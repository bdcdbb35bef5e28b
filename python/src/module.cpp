// turf._turf: the compiled part of `import turf` (python/turf/ is the rest).
// A refused input raises turf.TurfError (python/turf/errors.py) with the
// error's name from core/errors.h, the same names turf-sim's control replies
// and refusal counters use.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/errors.h"
#include "python/src/scene_source.h"
#include "python/src/sim_error.h"

namespace turf::py {
void BindSsl(pybind11::module_& m);
void BindLegged(pybind11::module_& m);
}  // namespace turf::py

PYBIND11_MODULE(_turf, m) {
  namespace pyb = pybind11;
  using turf::py::SimError;
  m.doc() = "turf's simulation kernels in this process (see the turf package)";
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
