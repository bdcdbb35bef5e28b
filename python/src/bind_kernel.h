// What both kinds of turf.Sim (SslSim, LeggedSim) bind alike: the constructor from a SceneRequest,
// check_commands, set_realism, save, and the kernel's properties (scene_name, seed, step_seconds, time, frame,
// realism). Each kind binds its own commands, observations and teleports.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/src/bind_util.h"
#include "python/src/scene_source.h"

namespace turf::py {

// `scene_arg` is pyb::arg("scene"), with or without a default.
template <class Sim, class SceneArg>
void BindConstructor(pyb::class_<Sim>& cls, SceneArg scene_arg) {
  using pyb::arg;
  cls.def(
      pyb::init([](const std::string& scene, std::optional<uint64_t> seed, const std::string& realism,
                   std::optional<double> physics_step, std::optional<int> robots_per_team,
                   std::optional<int> wall_segments) {
        return std::make_unique<Sim>(SceneRequest{scene, seed, realism, physics_step, robots_per_team, wall_segments});
      }),
      scene_arg, arg("seed") = pyb::none(), arg("realism") = "", arg("physics_step") = pyb::none(),
      arg("robots_per_team") = pyb::none(), arg("wall_segments") = pyb::none());
}

// check_commands(commands): `arrays(sim, commands, &batch)` turns the Python commands into the Sim's batch and
// returns the arrays the batch points into.
template <class Sim, class Batch, class Arrays>
void BindCheckCommands(pyb::class_<Sim>& cls, Arrays arrays) {
  cls.def(
      "check_commands",
      [arrays](Sim& sim, const pyb::object& commands) {
        sim.CheckIdle();
        std::vector<Batch> batch;
        const std::vector<pyb::array_t<double>> keep = arrays(sim, commands, &batch);
        sim.CheckCommands(batch);
      },
      pyb::arg("commands"), "Raises TurfError for what step(commands) would refuse; changes nothing.");
}

template <class Sim>
void BindKernelCommon(pyb::class_<Sim>& cls) {
  cls.def(
         "set_realism",
         [](Sim& sim, const std::string& preset, const pyb::object& values) {
           sim.CheckIdle();
           sim.SetRealism(preset, RealismValues(values));
         },
         pyb::arg("preset") = "", pyb::arg("values") = pyb::none())
      .def("save",
           [](const Sim& sim) {
             sim.CheckIdle();
             return pyb::bytes(sim.Save());
           })
      .def_property_readonly("scene_name",
                             [](const Sim& s) {
                               s.CheckIdle();
                               return s.kernel().scene().name;
                             })
      .def_property_readonly("seed",
                             [](const Sim& s) {
                               s.CheckIdle();
                               return s.kernel().scene().seed;
                             })
      .def_property_readonly("step_seconds",
                             [](const Sim& s) {
                               s.CheckIdle();
                               return s.kernel().world().step_ns() * 1e-9;
                             })
      .def_property_readonly("time",
                             [](const Sim& s) {
                               s.CheckIdle();
                               return s.kernel().time_ns() * 1e-9;
                             })
      .def_property_readonly("frame",
                             [](const Sim& s) {
                               s.CheckIdle();
                               return s.kernel().frame();
                             })
      .def_property_readonly("realism", [](const Sim& s) {
        s.CheckIdle();
        return RealismDict(s.kernel().realism());
      });
}

}  // namespace turf::py
