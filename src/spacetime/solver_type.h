// The description of an integrator (core/type_registry.h): its name, the GeoViS/Motion4D names that
// map onto it (docs/geovis-catalogue.md §13), its order and capabilities. The steppers are the
// templates of spacetime/integrators.h, dispatched on SolverKind; solver_type.cpp registers one
// entry per kind. init-solver's keys are the same for every integrator (scene/command_table.cpp).
#pragma once

#include "core/type_registry.h"
#include "spacetime/geodesic.h"

namespace geovis {

struct SolverType : TypeDescription {
  SolverKind kind = SolverKind::CashKarp45;
  int order = 0;                ///< order of the propagated solution
  bool separable_only = false;  ///< integrates y'' = f(y) only: KerrBL and Schwarzschild in Mino time
};
using SolverRegistry = TypeRegistry<SolverType>;

}  // namespace geovis
