#include "spacetime/horizon.h"

#include <cmath>

namespace geovis {

std::optional<CentralSurface> central_surface(const Metric& m) {
  const std::string& name = m.name();
  // Schwarzschild radius r_s = 2M in every chart whose radial coordinate is the areal radius r
  // (Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, section "Schwarzschild": Schwarzschild, ingoing
  // Eddington–Finkelstein, Painlevé–Gullstrand; the Cartesian chart has |p| = r too; the cosmic
  // string and Ernst metrics keep r_s = 2M).
  if (name == "Schwarzschild" || name == "SchwarzschildCart" || name == "EddFinkIn" || name == "PainleveGullstrand" ||
      name == "CosmicStringSchwarzschild" || name == "Ernst") {
    const double M = m.param("mass");
    if (!(M > 0)) return std::nullopt;
    return CentralSurface{"horizon", 2 * M, "r = 2M"};
  }
  // Isotropic coordinates: r = ρ (1 + M/(2ρ))², so r = 2M is ρ = M/2 (Catalogue of Spacetimes, "Schwarzschild",
  // isotropic coordinates).
  if (name == "SchwarzschildIsotropic") {
    const double M = m.param("mass");
    if (!(M > 0)) return std::nullopt;
    return CentralSurface{"horizon", M / 2, "rho = M/2 (r = 2M)"};
  }
  // Outer horizon r+ = M + sqrt(M² − a²) (Kerr, Boyer–Lindquist: Catalogue, "Kerr"; pseudo-Cartesian
  // radius r, Metric::to_pseudo_cartesian for spherical coordinates) and r+ = M + sqrt(M² − Q²)
  // (Reissner–Nordström: Catalogue, "Reissner-Nordstrom").
  if (name == "KerrBL" || name == "ReissnerNordstrom") {
    const double M = m.param("mass");
    const double q = name == "KerrBL" ? m.param("angmom") : m.param("charge");
    if (!(M > 0) || std::fabs(q) > M) return std::nullopt;
    return CentralSurface{"horizon", M + std::sqrt(M * M - q * q),
                          name == "KerrBL" ? "r+ = M + sqrt(M^2 - a^2)" : "r+ = M + sqrt(M^2 - Q^2)"};
  }
  // Morris–Thorne ds² = −dt² + dl² + (b0² + l²) dΩ² (Catalogue, "Morris-Thorne"): the throat is l = 0, the
  // pseudo-Cartesian origin (|p| = |l|; chart 1 is the other side, l < 0).
  if (name == "MorrisThorne") return CentralSurface{"throat", 0.0, "l = 0 (circumference 2 pi b0)"};
  return std::nullopt;
}

}  // namespace geovis
