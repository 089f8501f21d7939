#include "spacetime/motion_sampled.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/number_text.h"
#include "spacetime/dual.h"
#include "spacetime/metric.h"
#include "spacetime/tetrad.h"

namespace geovis {

namespace {

/// Quintic Hermite basis on s ∈ [0,1] (values/first/second derivatives at s = 0 and 1 are the
/// unit vectors): H0, H1, H2 for p(0), p'(0), p''(0) and H3, H4, H5 for p(1), p'(1), p''(1).
void quintic_basis(double s, double H[6], double dH[6]) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  H[0] = 1 - 10 * s3 + 15 * s4 - 6 * s5;
  H[1] = s - 6 * s3 + 8 * s4 - 3 * s5;
  H[2] = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5);
  H[3] = 10 * s3 - 15 * s4 + 6 * s5;
  H[4] = -4 * s3 + 7 * s4 - 3 * s5;
  H[5] = 0.5 * (s3 - 2 * s4 + s5);
  dH[0] = -30 * s2 + 60 * s3 - 30 * s4;
  dH[1] = 1 - 18 * s2 + 32 * s3 - 15 * s4;
  dH[2] = 0.5 * (2 * s - 9 * s2 + 12 * s3 - 5 * s4);
  dH[3] = 30 * s2 - 60 * s3 + 30 * s4;
  dH[4] = -12 * s2 + 28 * s3 - 15 * s4;
  dH[5] = 0.5 * (3 * s2 - 8 * s3 + 5 * s4);
}

}  // namespace

Vec4 SampledMotion::lowered_e0_rate(const MotionNode& n, const Mat4& g) const {
  // Between nodes event_at evaluates e_(0)(τ) = u(τ)/|u(τ)| with u the interpolant's derivative,
  // which at the node is n.u with derivative n.du. d/dτ (g_{μν} e_(0)^μ) = (∂_u g)_{μν} e_(0)^μ
  // + g_{μν} de_(0)^μ/dτ, de_(0)/dτ = (du − e_(0) d|u|/dτ)/|u|, d|u|/dτ = −[(∂_u g)(u, u)
  // + 2 g(u, du)]/(2|u|) (from |u|² = −g(u, u)); ∂_u g = u^λ ∂_λ g by dual numbers (exact).
  Mat4T<DualD> gd;
  metric_->metric_tensor(seed(n.x), gd);
  Mat4 dg{};  // (∂_u g)_{μν}
  for (int mu = 0; mu < 4; ++mu)
    for (int nu = 0; nu < 4; ++nu)
      for (int la = 0; la < 4; ++la) dg[mu][nu] += gd[mu][nu].d[la] * n.u[la];
  const double norm_u = std::sqrt(-dot(g, n.u, n.u));
  const Vec4 e0 = (1.0 / norm_u) * n.u;
  const double dnorm = -(dot(dg, n.u, n.u) + 2 * dot(g, n.u, n.du)) / (2 * norm_u);
  const Vec4 de0 = (1.0 / norm_u) * (n.du - dnorm * e0);
  Vec4 rate{{0, 0, 0, 0}};
  for (int nu = 0; nu < 4; ++nu)
    for (int mu = 0; mu < 4; ++mu) rate[nu] += dg[mu][nu] * e0[mu] + g[mu][nu] * de0[mu];
  return rate;
}

void SampledMotion::set_nodes(std::vector<MotionNode> nodes) {
  if (nodes.empty()) throw Error("motion has no samples");
  nodes_ = std::move(nodes);
  samples_.clear();
  samples_.reserve(nodes_.size());
  node_g_.resize(nodes_.size());
  node_g_diagonal_.resize(nodes_.size());
  node_u_norm_.resize(nodes_.size());
  node_e0_rate_.resize(nodes_.size());
  node_tau_.clear();
  node_tau_.reserve(nodes_.size());
  x0_increasing_ = true;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const MotionNode& n = nodes_[i];
    samples_.push_back(MotionSample{n.tau, n.x, n.u, n.e});
    node_tau_.push_back(n.tau);
    metric_->metric_tensor(n.x, node_g_[i]);
    node_g_diagonal_[i] = is_diagonal(node_g_[i]);
    node_u_norm_[i] = -dot_skipping_zeros(node_g_[i], n.e[0], n.u);
    node_e0_rate_[i] = lowered_e0_rate(n, node_g_[i]);
    if (i > 0 && !(n.x[0] > nodes_[i - 1].x[0])) x0_increasing_ = false;
  }
}

size_t SampledMotion::interval(double tau, size_t hint) const {
  // The common cases first: τ inside the hinted interval or a neighbour of it (a Newton step from
  // a node often ends in the interval before), not the last interval (whose end the range check
  // below bounds): there that check cannot fail, and the intervals [τ_i, τ_{i+1}) below the last
  // one are disjoint, so the index is the one the search below would find.
  auto inside = [&](size_t i) { return i + 2 < nodes_.size() && nodes_[i].tau <= tau && tau < nodes_[i + 1].tau; };
  if (inside(hint)) return hint;
  if (hint > 0 && inside(hint - 1)) return hint - 1;
  if (inside(hint + 1)) return hint + 1;
  const double lo = nodes_.front().tau, hi = nodes_.back().tau;
  const double slack = 1e-12 * std::max({1.0, std::fabs(lo), std::fabs(hi)});
  if (!(tau >= lo - slack && tau <= hi + slack))
    throw Error(std::string(type_name()) + " motion: proper time " + number_text(tau) +
                " is outside the computed range [" + number_text(lo) + ", " + number_text(hi) +
                "] (extend it with `forward`/`backward` or `maxnumpoints`)");
  if (nodes_.size() == 1) return 0;
  // The last i <= size − 2 with τ_i <= τ (0 below the first node): the last interval, τ within
  // the slack of the range, and hints far from τ.
  auto it = std::upper_bound(node_tau_.begin(), node_tau_.end(), tau);
  size_t i = static_cast<size_t>(it - node_tau_.begin());
  i = i == 0 ? 0 : i - 1;
  return std::min(i, nodes_.size() - 2);
}

const MotionSample* SampledMotion::node_at(size_t i, double tau) const {
  if (nodes_.size() == 1) return &samples_[0];
  if (tau == nodes_[i].tau) return &samples_[i];
  if (tau == nodes_[i + 1].tau) return &samples_[i + 1];
  return nullptr;
}

void SampledMotion::interpolate_x(size_t i, double tau, Vec4& x, Vec4& u) const {
  const MotionNode& a = nodes_[i];
  const MotionNode& b = nodes_[i + 1];
  const double h = b.tau - a.tau;
  const double s = (tau - a.tau) / h;
  double H[6], dH[6];
  quintic_basis(s, H, dH);
  for (int mu = 0; mu < 4; ++mu) {
    x[mu] = H[0] * a.x[mu] + h * H[1] * a.u[mu] + h * h * H[2] * a.du[mu] + H[3] * b.x[mu] + h * H[4] * b.u[mu] +
            h * h * H[5] * b.du[mu];
    u[mu] = (dH[0] * a.x[mu] + dH[3] * b.x[mu]) / h + dH[1] * a.u[mu] + h * dH[2] * a.du[mu] + dH[4] * b.u[mu] +
            h * dH[5] * b.du[mu];
  }
}

MotionSample SampledMotion::at_proper_time(double tau) const {
  WorldlineEvent ev;
  event_at(tau, ev);
  if (ev.node) return *ev.node;
  return MotionSample{tau, ev.x, ev.e0, frame_at(ev)};
}

void SampledMotion::event_at(double tau, WorldlineEvent& ev) const {
  const size_t i = interval(tau, ev.interval);
  ev.tau = tau;
  ev.interval = i;
  ev.node = node_at(i, tau);
  if (ev.node) {
    ev.x = ev.node->x;
    ev.e0 = ev.node->e[0];
    const size_t k = static_cast<size_t>(ev.node - samples_.data());
    ev.g = node_g_[k];
    ev.g_diagonal = node_g_diagonal_[k];
    ev.u_norm = node_u_norm_[k];
    ev.e0_rate = node_e0_rate_[k];
    return;
  }
  // e_(0) is the normalized u(τ): the first Gram-Schmidt step of frame_at.
  Vec4 u;
  interpolate_x(i, tau, ev.x, u);
  metric_->metric_tensor(ev.x, ev.g);
  ev.g_diagonal = is_diagonal(ev.g);
  ev.e0 = unit_timelike(*metric_, ev.x, ev.g, u);
  ev.u_norm = -dot_skipping_zeros(ev.g, ev.g_diagonal, ev.e0, u);
  // The nodes' rates interpolated linearly (a slope for Newton's method: its error, O(h²) of the
  // rate's change, only slows the convergence to the same root).
  const double s = (tau - nodes_[i].tau) / (nodes_[i + 1].tau - nodes_[i].tau);
  ev.e0_rate = (1 - s) * node_e0_rate_[i] + s * node_e0_rate_[i + 1];
}

Tetrad SampledMotion::frame_at(const WorldlineEvent& ev) const {
  if (ev.node) return ev.node->e;
  const MotionNode& a = nodes_[ev.interval];
  const MotionNode& b = nodes_[ev.interval + 1];
  // Cubic Hermite for the tetrad vectors (they satisfy a first-order ODE whose derivative is
  // stored at the nodes), then Gram-Schmidt against g at x(τ) with e_(0) from the event.
  const double h = b.tau - a.tau;
  const double s = (ev.tau - a.tau) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  Tetrad e{};
  for (int c = 1; c < 4; ++c)
    for (int mu = 0; mu < 4; ++mu)
      e[c][mu] = h00 * a.e[c][mu] + h * h10 * a.de[c][mu] + h01 * b.e[c][mu] + h * h11 * b.de[c][mu];
  return gram_schmidt_after_e0(*metric_, ev.x, ev.g, ev.e0, e);
}

Tetrad SampledMotion::frame_derivative_at(double tau, size_t interval_hint) const {
  const size_t i = interval(tau, interval_hint);
  Tetrad de{};
  if (const MotionSample* node = node_at(i, tau)) {
    const MotionNode& n = nodes_[static_cast<size_t>(node - samples_.data())];
    for (int c = 1; c < 4; ++c) de[c] = n.de[c];
    return de;
  }
  // d/dτ of frame_at's cubic Hermite polynomial: (1/h) d/ds of its basis.
  const MotionNode& a = nodes_[i];
  const MotionNode& b = nodes_[i + 1];
  const double h = b.tau - a.tau;
  const double s = (tau - a.tau) / h;
  const double s2 = s * s;
  const double d00 = (6 * s2 - 6 * s) / h, d10 = 3 * s2 - 4 * s + 1, d01 = -d00, d11 = 3 * s2 - 2 * s;
  for (int c = 1; c < 4; ++c)
    for (int mu = 0; mu < 4; ++mu)
      de[c][mu] = d00 * a.e[c][mu] + d10 * a.de[c][mu] + d01 * b.e[c][mu] + d11 * b.de[c][mu];
  return de;
}

void SampledMotion::event_at_proper_time(double tau, Vec4& x, Vec4& u) const {
  Mat4 g;
  event_at_proper_time(tau, x, u, g);
}

void SampledMotion::event_at_proper_time(double tau, Vec4& x, Vec4& u, Mat4& g) const {
  WorldlineEvent ev;
  event_at(tau, ev);
  x = ev.x;
  u = ev.e0;
  g = ev.g;
}

double SampledMotion::proper_time_at_coordinate_time(double t) const {
  const double t_lo = nodes_.front().x[0], t_hi = nodes_.back().x[0];
  if (!x0_increasing_)
    throw Error(std::string(type_name()) +
                " motion: the coordinate time x^0 does not increase along the motion, so "
                "an event cannot be selected by coordinate time");
  const double slack = 1e-12 * std::max({1.0, std::fabs(t_lo), std::fabs(t_hi)});
  if (!(t >= t_lo - slack && t <= t_hi + slack))
    throw Error(std::string(type_name()) + " motion: coordinate time " + number_text(t) +
                " is outside the computed range [" + number_text(t_lo) + ", " + number_text(t_hi) +
                "] (extend it with `forward`/`backward` or `maxnumpoints`)");
  if (nodes_.size() == 1) return nodes_[0].tau;
  auto it =
      std::upper_bound(nodes_.begin(), nodes_.end(), t, [](double tt, const MotionNode& n) { return tt < n.x[0]; });
  size_t i = static_cast<size_t>(it - nodes_.begin());
  i = std::min(i == 0 ? 0 : i - 1, nodes_.size() - 2);
  const MotionNode& a = nodes_[i];
  const MotionNode& b = nodes_[i + 1];
  if (t <= a.x[0]) return a.tau;
  if (t >= b.x[0]) return b.tau;
  // Safeguarded Newton on f(τ) = x^0(τ) − t with f' = u^0 (the bracket [lo, hi] always keeps a
  // sign change; a Newton step leaving it is replaced by bisection).
  double lo = a.tau, hi = b.tau;
  double tau = a.tau + (b.tau - a.tau) * (t - a.x[0]) / (b.x[0] - a.x[0]);
  for (int iter = 0; iter < 100; ++iter) {
    Vec4 x, u;
    interpolate_x(i, tau, x, u);
    const double f = x[0] - t;
    if (f > 0)
      hi = tau;
    else
      lo = tau;
    if (std::fabs(f) <= 1e-14 * std::max(1.0, std::fabs(t))) break;
    double next = u[0] != 0 ? tau - f / u[0] : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - tau) <= 1e-15 * std::max(1.0, std::fabs(tau))) {
      tau = next;
      break;
    }
    tau = next;
  }
  return tau;
}

MotionSample SampledMotion::at_coordinate_time(double t) const {
  return at_proper_time(proper_time_at_coordinate_time(t));
}

}  // namespace geovis
