// A pybind11 stand-in for Python-RVO2's `rvo2` module (a thin wrapper of RVO2's C++ simulator):
// only the calls CrowdNav's ORCA policy and env make, with Python-RVO2's argument order.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <utility>

#include "RVO.h"

namespace py = pybind11;
using Pair = std::pair<double, double>;

namespace {
RVO::Vector2 V(const Pair& p) {
  return RVO::Vector2(static_cast<float>(p.first), static_cast<float>(p.second));
}
Pair P(const RVO::Vector2& v) { return {v.x(), v.y()}; }
}  // namespace

PYBIND11_MODULE(rvo2, m) {
  py::class_<RVO::RVOSimulator>(m, "PyRVOSimulator")
      .def(py::init([](float time_step, float neighbor_dist, size_t max_neighbors,
                       float time_horizon, float time_horizon_obst, float radius, float max_speed,
                       const Pair& velocity) {
             return new RVO::RVOSimulator(time_step, neighbor_dist, max_neighbors, time_horizon,
                                          time_horizon_obst, radius, max_speed, V(velocity));
           }),
           py::arg("timeStep"), py::arg("neighborDist"), py::arg("maxNeighbors"),
           py::arg("timeHorizon"), py::arg("timeHorizonObst"), py::arg("radius"),
           py::arg("maxSpeed"), py::arg("velocity") = Pair{0.0, 0.0})
      .def(
          "addAgent",
          [](RVO::RVOSimulator& s, const Pair& position, float neighbor_dist, size_t max_neighbors,
             float time_horizon, float time_horizon_obst, float radius, float max_speed,
             const Pair& velocity) {
            return s.addAgent(V(position), neighbor_dist, max_neighbors, time_horizon,
                              time_horizon_obst, radius, max_speed, V(velocity));
          },
          py::arg("pos"), py::arg("neighborDist"), py::arg("maxNeighbors"), py::arg("timeHorizon"),
          py::arg("timeHorizonObst"), py::arg("radius"), py::arg("maxSpeed"),
          py::arg("velocity") = Pair{0.0, 0.0})
      .def("doStep", &RVO::RVOSimulator::doStep)
      .def("getNumAgents", &RVO::RVOSimulator::getNumAgents)
      .def("getAgentVelocity",
           [](const RVO::RVOSimulator& s, size_t i) { return P(s.getAgentVelocity(i)); })
      .def("getAgentPosition",
           [](const RVO::RVOSimulator& s, size_t i) { return P(s.getAgentPosition(i)); })
      .def("setAgentPosition",
           [](RVO::RVOSimulator& s, size_t i, const Pair& p) { s.setAgentPosition(i, V(p)); })
      .def("setAgentVelocity",
           [](RVO::RVOSimulator& s, size_t i, const Pair& v) { s.setAgentVelocity(i, V(v)); })
      .def("setAgentPrefVelocity",
           [](RVO::RVOSimulator& s, size_t i, const Pair& v) { s.setAgentPrefVelocity(i, V(v)); });
}
