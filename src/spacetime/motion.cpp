#include "spacetime/motion.h"

#include <ostream>

#include "core/number_text.h"

namespace geovis {

void Motion::write(std::ostream& os) const {
  // One line per sample: tau, x^μ, u^μ, then e_(0)^μ .. e_(3)^μ; 17 significant digits so the file
  // reproduces the doubles exactly.
  os << "# " << type_name() << " motion: tau x0 x1 x2 x3 u0 u1 u2 u3 e0^0 e0^1 e0^2 e0^3 ... e3^3\n";
  auto put = [&](double v, bool first = false) {
    if (!first) os << ' ';
    os << exact_number_text(v);
  };
  for (const MotionSample& s : samples()) {
    put(s.tau, true);
    for (int i = 0; i < 4; ++i) put(s.x[i]);
    for (int i = 0; i < 4; ++i) put(s.u[i]);
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 4; ++i) put(s.e[a][i]);
    os << '\n';
  }
}

}  // namespace geovis
