// Sim.publish(domain=...), Sim.unpublish(), Sim.publishing, Sim.state_readers for both kinds of Sim
// (publication.h).
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "python/src/bind_util.h"
#include "python/src/publication.h"

namespace turf::py {

template <class Sim>
void BindPublish(pyb::class_<Sim>& cls) {
  cls.def(
         "publish",
         [](Sim& sim, int domain, const std::string& prefix, const std::string& qos_file) {
           sim.CheckIdle();
           PublishOptions o;
           o.domain = domain;
           o.prefix = prefix;
           o.qos_file = qos_file;
           sim.Publish(o);
         },
         pyb::arg("domain") = 0, pyb::arg("prefix") = "turf", pyb::arg("qos_file") = "",
         "From now on, publish this world's topics on DDS `domain` under `prefix` as turf-sim does (the viewer, "
         "turf-record and team tools watch it); watch-only: nothing is subscribed. Replaces an earlier publish().")
      .def(
          "unpublish",
          [](Sim& sim) {
            sim.CheckIdle();
            sim.Unpublish();
          },
          "Stops publishing (leaves the DDS domain).")
      .def_property_readonly(
          "publishing",
          [](const Sim& sim) -> pyb::object {
            sim.CheckIdle();
            if (sim.publication() == nullptr) return pyb::none();
            pyb::dict d;
            d["domain"] = sim.publication()->options().domain;
            d["prefix"] = sim.publication()->options().prefix;
            d["description"] = sim.publication()->Describe();
            return d;
          },
          "None, or the domain and prefix publish() was given")
      .def_property_readonly(
          "state_readers",
          [](const Sim& sim) {
            sim.CheckIdle();
            return sim.publication() ? sim.publication()->StateReaders() : 0;
          },
          "DDS readers matched to the published state topic (world_state; legged scenes: robots/state)");
}

}  // namespace turf::py
