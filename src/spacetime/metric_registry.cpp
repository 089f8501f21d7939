#include "spacetime/metric_registry.h"

#include "core/error.h"

// One line per metric: X(ClassName, "DatabaseName"). make_metric_<ClassName>() is defined in
// spacetime/metrics/<file>.cpp.
#define GEOVIS_METRICS(X)                                             \
  X(Minkowski, "Minkowski")                                           \
  X(Schwarzschild, "Schwarzschild")                                   \
  X(KerrBL, "KerrBL")                                                 \
  X(MorrisThorne, "MorrisThorne")                                     \
  X(TeoSimpleWH, "TeoSimpleWH")                                       \
  X(KastorTraschen, "KastorTraschen")                                 \
  X(AlcubierreWarpSimple, "AlcubierreWarpSimple")                     \
  X(EinsteinRosenWaveWWB, "EinsteinRosenWaveWWB")                     \
  X(RotDihole, "RotDihole")                                           \
  X(DeSitterUniv, "DeSitterUniv")                                     \
  X(SchwarzschildCart, "SchwarzschildCart")                           \
  X(SchwarzschildIsotropic, "SchwarzschildIsotropic")                 \
  X(EddFinkIn, "EddFinkIn")                                           \
  X(PainleveGullstrand, "PainleveGullstrand")                         \
  X(ReissnerNordstrom, "ReissnerNordstrom")                           \
  X(Kottler, "Kottler")                                               \
  X(BarriolaVilenkin, "BarriolaVilenkin")                             \
  X(JanisNewmanWinicour, "JanisNewmanWinicour")                       \
  X(Ernst, "Ernst")                                                   \
  X(TaubNUT, "TaubNUT")                                               \
  X(Goedel, "Goedel")                                                 \
  X(GoedelCart, "GoedelCart")                                         \
  X(GoedelScaled, "GoedelScaled")                                     \
  X(GoedelScaledCart, "GoedelScaledCart")                             \
  X(Kasner, "Kasner")                                                 \
  X(Curzon, "Curzon")                                                 \
  X(CosmicStringSchwarzschild, "CosmicStringSchwarzschild")           \
  X(MinkowskiConformal, "MinkowskiConformal")                         \
  X(SchwarzschildTortoise, "SchwarzschildTortoise")                   \
  X(MinkowskiRotLattice, "MinkowskiRotLattice")                       \
  X(StraightSpinningString, "StraightSpinningString")                 \
  X(BertottiKasner, "BertottiKasner")                                 \
  X(DeSitterUnivConformal, "DeSitterUnivConformal")                   \
  X(PetrovTypeD_AI, "Petrov_Type_D_AI_ES")                            \
  X(PetrovTypeD_AII, "Petrov_Type_D_AII_ES")                          \
  X(ExtremeReissnerNordstromDihole, "ExtremeReissnerNordstromDihole") \
  X(SchwarzschildWT, "SchwarzschildWT")                               \
  X(Kruskal, "Kruskal")                                               \
  X(VaidyaIncRad, "VaidyaIncRad")                                     \
  X(SultanaDyerBlackhole, "SultanaDyerBlackhole")                     \
  X(FriedmanNonEmptyNull, "FriedmanNonEmptyNull")                     \
  X(TeoWHl, "TeoWHl")                                                 \
  X(PetrovTypeD_AIII, "Petrov_Type_D_AIII_ES")                        \
  X(PetrovTypeD_BI, "Petrov_Type_D_BI_ES")                            \
  X(PetrovTypeD_BII, "Petrov_Type_D_BII_ES")                          \
  X(PetrovTypeD_BIII, "Petrov_Type_D_BIII_ES")                        \
  X(PetrovTypeD_C, "Petrov_Type_D_C_ES")                              \
  X(PravdaCMetric, "Pravda_C-Metric")                                 \
  X(PravdaCMetricCanonical, "Pravda_C-Metric_Canonical_Coords")       \
  X(SchwarzschildGravWave, "SchwarzschildGravWave")                   \
  X(PlaneGravWave, "PlaneGravWave")                                   \
  X(BesselGravWaveCart, "BesselGravWaveCart")                         \
  X(HalilsoyWave, "HalilsoyWave")                                     \
  X(Bonnor, "Bonnor")                                                 \
  X(AlcubierreWarp, "AlcubierreWarp")                                 \
  X(ChazyCurzonRot, "ChazyCurzonRot")                                 \
  X(TomimatsuSato, "TomimatsuSato")                                   \
  X(Glampedakis, "Glampedakis")                                       \
  X(HartleThorneGB, "HartleThorneGB")                                 \
  X(ErezRosenVar, "ErezRosenVar")

namespace geovis {

#define GEOVIS_DECLARE(cls, name) std::unique_ptr<Metric> make_metric_##cls();
GEOVIS_METRICS(GEOVIS_DECLARE)
#undef GEOVIS_DECLARE

namespace {
struct Entry {
  const char* name;
  std::unique_ptr<Metric> (*make)();
};
const std::vector<Entry>& entries() {
#define GEOVIS_ENTRY(cls, name) Entry{name, &make_metric_##cls},
  static const std::vector<Entry> list = {GEOVIS_METRICS(GEOVIS_ENTRY)};
#undef GEOVIS_ENTRY
  return list;
}
}  // namespace

std::vector<std::string> metric_names() {
  std::vector<std::string> out;
  for (const auto& e : entries()) out.emplace_back(e.name);
  return out;
}

std::unique_ptr<Metric> make_metric(const std::string& name) {
  for (const auto& e : entries())
    if (name == e.name) return e.make();
  throw Error("unknown metric \"" + name + "\"" + did_you_mean(name, metric_names()) +
              " (valid metrics: " + join(metric_names()) + ")");
}

std::unique_ptr<Metric> make_metric(const std::string& name,
                                    const std::vector<std::pair<std::string, double>>& params) {
  auto m = make_metric(name);
  m->set_params(params);
  return m;
}

}  // namespace geovis
