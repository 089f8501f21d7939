// The integrators and the GeoViS/Motion4D names that map onto them (docs/geovis-catalogue.md §13).
// GSL's implicit methods (Gaussian points, Gear) target stiff problems; geodesics are not stiff, so
// they map onto the explicit method of the same order with step control. GSL's rk8pd
// (Prince-Dormand 8(7)) and Motion4D's DP65 map onto the closest high-order method we have, DOP853.
#include "spacetime/solver_type.h"

namespace geovis {

namespace {

const TypeRegistrar<SolverType> rk2{
    {{"RK2",
      {"GSL_RK2", "GSL: Embedded 2nd order Runge-Kutta", "GSL_RK_Gaussian-points", "GSL_M1_IG", "GSL_M2_IG",
       "GSL: Implicit 2nd order Runge-Kutta at Gaussian points", "GSL: M=1 implicit Gear", "GSL: M=2 implicit Gear"},
      "Heun-Euler embedded 2(1); GSL's implicit 2nd-order methods map onto it",
      {}},
     SolverKind::RK2,
     2}};

const TypeRegistrar<SolverType> rk4{
    {{"RK4",
      {"GSL_RK4", "Runge-Kutta (fourth order)", "GSL: 4th order (classical) Runge-Kutta"},
      "classical 4th-order Runge-Kutta, fixed step (Motion4D GeodesicRK4)",
      {}},
     SolverKind::RK4,
     4}};

const TypeRegistrar<SolverType> cash_karp{
    {{"CashKarp45",
      {"CashKarp", "GSL_RK_Cash-Karp", "GSL: Embedded 4th order Runge-Kutta Cash-Karp"},
      "Runge-Kutta Cash-Karp 4(5)",
      {}},
     SolverKind::CashKarp45,
     5}};

const TypeRegistrar<SolverType> fehlberg{
    {{"Fehlberg45",
      {"Fehlberg", "GSL_RK_Fehlberg", "GSL: Embedded 4th order Runge-Kutta-Fehlberg"},
      "Runge-Kutta-Fehlberg 4(5)",
      {}},
     SolverKind::Fehlberg45,
     4}};

const TypeRegistrar<SolverType> dormand_prince54{
    {{"DormandPrince54", {"DP54", "Dormand-Prince: RK5(4)"}, "Dormand-Prince 5(4), FSAL", {}},
     SolverKind::DormandPrince54,
     5}};

const TypeRegistrar<SolverType> dop853{
    {{"DOP853",
      {"DP853", "GSL_RK_Prince-Dormand", "GSL: Embedded 8th order Runge-Kutta Prince-Dormand", "DP65",
       "Dormand-Prince: RK6(5)"},
      "Dormand-Prince 8(5,3) (Hairer's DOP853); GSL's rk8pd and Motion4D's DP65 map onto it",
      {}},
     SolverKind::DormandPrince853,
     8}};

const TypeRegistrar<SolverType> bulirsch_stoer{
    {{"BulirschStoer", {"BS", "Bulirsch-Stoer"}, "Gragg-Bulirsch-Stoer extrapolation (Motion4D GeodesicBS)", {}},
     SolverKind::BulirschStoer,
     8}};

const TypeRegistrar<SolverType> rkn86{
    {{"RKN86",
      {},
      "Runge-Kutta-Nystrom 8(6) (Dormand, El-Mikkawy & Prince); KerrBL and Schwarzschild geodesics only",
      {},
      {},
      true},
     SolverKind::RungeKuttaNystrom86,
     8,
     true}};

}  // namespace

}  // namespace geovis
