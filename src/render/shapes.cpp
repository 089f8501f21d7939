#include "render/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "render/object_type.h"

namespace geovis {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTwoPi = 6.283185307179586476925286766559;

/// Real roots t0 <= t1 of A t² + B t + C = 0 (numerically stable form, Press et al., Numerical
/// Recipes §5.6). False when there is none.
bool solve_quadratic(double A, double B, double C, double& t0, double& t1) {
  if (A == 0) return false;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return false;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  t0 = q / A;
  t1 = q != 0 ? C / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

Crossing make_crossing(double t, const SolidPrimitive* prim, const Vec3& o, const Vec3& d, int part) {
  Crossing c;
  c.t = t;
  c.prim = prim;
  c.p_local = o + t * d;
  c.d_local = d;
  c.part = part;
  return c;
}
}  // namespace

// ---- Affine3 ------------------------------------------------------------------------------------

Affine3 Affine3::from(const Transform& t) {
  Affine3 a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] = t(r, c);
  return a;
}

Transform Affine3::to_transform() const {
  Transform t = Transform::identity(3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t(r, c) = m[r][c];
  return t;
}

Affine3 Affine3::inverse() const { return from(to_transform().inverse()); }

bool Affine3::is_identity() const {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c)
      if (m[r][c] != (r == c ? 1.0 : 0.0)) return false;
  return true;
}

Bounds3 Affine3::bounds(const Bounds3& b) const {
  if (b.empty()) return b;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i])) return Bounds3::infinite();
  Bounds3 r;
  for (int k = 0; k < 8; ++k)
    r.expand(point({(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z}));
  return r;
}

void PrimitiveData::set_transform(const Transform& t) {
  to_parent = Affine3::from(t);
  to_local = to_parent.inverse();
  transformed = !to_parent.is_identity();
}

// ---- Solid --------------------------------------------------------------------------------------

void fill_hit_from_crossing(const Crossing& c, const Segment& seg, Hit& hit) {
  const Vec3 d = seg.p1 - seg.p0;
  hit.s = c.t;
  hit.point = seg.p0 + c.t * d;
  Vec3 n = c.prim->parent_normal(c.p_local, c.part);
  hit.normal = c.flip ? -n : n;
  hit.ray_dir = normalize(d);
  c.prim->shading_frame(c.p_local, c.d_local, c.part, hit.shade_normal, hit.shade_dir);
  if (c.flip) hit.shade_normal = -hit.shade_normal;
  c.prim->uv(c.p_local, c.part, hit.u, hit.v);
  hit.shader = c.prim->shader;
  hit.object_id = c.prim->object_id;
  hit.time = seg.x0[0] + c.t * (seg.x1[0] - seg.x0[0]);
  hit.emitter_u = Vec4{{0, 0, 0, 0}};
  hit.keplerian = false;
  hit.part = c.part;
}

bool Solid::intersect(const Segment& seg, Hit& hit) const {
  if (seg.chart0 != chart || seg.chart1 != chart) return false;
  const Vec3 d = seg.p1 - seg.p0;
  if (d.x == 0 && d.y == 0 && d.z == 0) return false;
  SpanList list;
  spans(seg.p0, d, list);
  const double tmax = std::min(1.0, hit.s);
  for (int i = 0; i < list.n; ++i) {
    const Span& sp = list.s[i];
    const Crossing* c = nullptr;
    if (sp.in.t >= 0)
      c = &sp.in;
    else if (sp.out.t >= 0)
      c = &sp.out;
    if (!c) continue;
    if (c->t >= tmax) return false;  // sorted: nothing closer follows
    fill_hit_from_crossing(*c, seg, hit);
    return true;
  }
  return false;
}

void SolidPrimitive::spans(const Vec3& a, const Vec3& d, SpanList& out) const {
  if (!transformed) {
    local_spans(a, d, out);
    return;
  }
  local_spans(to_local.point(a), to_local.dir(d), out);
}

Bounds3 SolidPrimitive::bounds() const { return transformed ? to_parent.bounds(local_bounds()) : local_bounds(); }

Vec3 SolidPrimitive::parent_normal(const Vec3& p_local, int part) const {
  const Vec3 n = local_normal(p_local, part);
  return transformed ? normalize(to_local.transposed_dir(n)) : n;
}

// ---- Ellipsoid ----------------------------------------------------------------------------------

void Ellipsoid::local_spans(const Vec3& o, const Vec3& d, SpanList& out) const {
  // Unit sphere in q = (x − c)/a: |q + t dq|² = 1.
  const Vec3 q{(o.x - center.x) / axlen.x, (o.y - center.y) / axlen.y, (o.z - center.z) / axlen.z};
  const Vec3 dq{d.x / axlen.x, d.y / axlen.y, d.z / axlen.z};
  double t0, t1;
  if (!solve_quadratic(dot(dq, dq), 2 * dot(q, dq), dot(q, q) - 1, t0, t1)) return;
  out.push({make_crossing(t0, this, o, d, 0), make_crossing(t1, this, o, d, 0)});
}

Bounds3 Ellipsoid::local_bounds() const { return {center - axlen, center + axlen}; }

double Ellipsoid::outer_radius() const {
  if (transformed) return bounds().farthest_distance_from_origin();
  return norm(center) + std::max({std::fabs(axlen.x), std::fabs(axlen.y), std::fabs(axlen.z)});
}

Vec3 Ellipsoid::local_normal(const Vec3& p, int) const {
  // Gradient of Σ ((x_i − c_i)/a_i)².
  return normalize(Vec3{(p.x - center.x) / (axlen.x * axlen.x), (p.y - center.y) / (axlen.y * axlen.y),
                        (p.z - center.z) / (axlen.z * axlen.z)});
}

void ellipsoid_uv(const Vec3& n, double& u, double& v) {
  const double nz = std::clamp(n.z, -1.0, 1.0);
  v = std::acos(-nz) / M_PI;
  const double s = std::sqrt(std::max(0.0, 1.0 - nz * nz));
  u = s > 0 ? std::acos(std::clamp(n.x / s, -1.0, 1.0)) / kTwoPi : 0.0;
  if (n.y < 0) u = 1.0 - u;
}

void Ellipsoid::uv(const Vec3& p, int, double& u, double& v) const {
  const Vec3 q{(p.x - center.x) / axlen.x, (p.y - center.y) / axlen.y, (p.z - center.z) / axlen.z};
  ellipsoid_uv(normalize(q), u, v);
}

void Ellipsoid::shading_frame(const Vec3& p, const Vec3& d, int, Vec3& n, Vec3& dir) const {
  // Unit sphere q = (p − c)/a (GvsSolEllipsoid: the normal is the local point).
  n = normalize(Vec3{(p.x - center.x) / axlen.x, (p.y - center.y) / axlen.y, (p.z - center.z) / axlen.z});
  dir = normalize(Vec3{d.x / axlen.x, d.y / axlen.y, d.z / axlen.z});
}

// ---- Box ----------------------------------------------------------------------------------------

Box::Box(const Vec3& c0, const Vec3& c1)
    : lo{std::min(c0.x, c1.x), std::min(c0.y, c1.y), std::min(c0.z, c1.z)},
      hi{std::max(c0.x, c1.x), std::max(c0.y, c1.y), std::max(c0.z, c1.z)} {}

void Box::local_spans(const Vec3& o, const Vec3& d, SpanList& out) const {
  double tin = -kInf, tout = kInf;
  int fin = 0, fout = 0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (o[i] < lo[i] || o[i] > hi[i]) return;
      continue;
    }
    double ta = (lo[i] - o[i]) / d[i], tb = (hi[i] - o[i]) / d[i];
    int fa = 2 * i, fb = 2 * i + 1;
    if (ta > tb) {
      std::swap(ta, tb);
      std::swap(fa, fb);
    }
    if (ta > tin) tin = ta, fin = fa;
    if (tb < tout) tout = tb, fout = fb;
  }
  if (tin > tout || !std::isfinite(tin) || !std::isfinite(tout)) return;
  out.push({make_crossing(tin, this, o, d, fin), make_crossing(tout, this, o, d, fout)});
}

Vec3 Box::local_normal(const Vec3&, int part) const {
  Vec3 n{0, 0, 0};
  n[part / 2] = (part % 2) ? 1.0 : -1.0;
  return n;
}

void Box::shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const {
  // Unit cube [0,1]³ (GvsSolBox): the face normals are the axes.
  n = local_normal(p, part);
  dir = normalize(Vec3{d.x / (hi.x - lo.x), d.y / (hi.y - lo.y), d.z / (hi.z - lo.z)});
}

void Box::uv(const Vec3& p, int part, double& u, double& v) const {
  const Vec3 q{(p.x - lo.x) / (hi.x - lo.x), (p.y - lo.y) / (hi.y - lo.y), (p.z - lo.z) / (hi.z - lo.z)};
  switch (part) {
    case 0: u = 1.0 - q.y, v = q.z; break;
    case 1: u = q.y, v = q.z; break;
    case 2: u = q.x, v = q.z; break;
    case 3: u = 1.0 - q.x, v = q.z; break;
    default: u = q.x, v = q.y; break;
  }
}

// ---- cylinders ----------------------------------------------------------------------------------

CylinderFrame::CylinderFrame(const Vec3& b, const Vec3& top) : base(b) {
  const Vec3 axis = top - b;
  height = norm(axis);
  ez = axis / height;
  const double alpha = std::atan2(axis.y, axis.x);
  const double beta = std::atan2(std::hypot(axis.x, axis.y), axis.z);
  e1 = {std::cos(alpha) * std::cos(beta), std::sin(alpha) * std::cos(beta), -std::sin(beta)};
  e2 = {-std::sin(alpha), std::cos(alpha), 0.0};
}

namespace {
/// GvsSolCylinder/GvsSolRing::calcTexUVParam at the point l of the unit cylinder: caps
/// u = (atan2(y, x) + π)/2π, v = √(x² + y²); side u = acos(x)/2π (1 − that for y < 0), v = z.
void unit_cylinder_uv(const Vec3& l, bool cap, double& u, double& v) {
  if (cap) {
    u = (std::atan2(l.y, l.x) + M_PI) / kTwoPi;
    v = std::hypot(l.x, l.y);
  } else {
    const double a = std::acos(std::clamp(l.x, -1.0, 1.0)) / kTwoPi;
    u = l.y < 0 ? 1.0 - a : a;
    v = l.z;
  }
}

/// Normal and unit direction in the unit cylinder of radii (r1, r2) and height h (point l of the
/// unit cylinder, frame direction dq): caps ∓ẑ, side (x, y, 0)/|…|.
void unit_cylinder_shading(const Vec3& l, const Vec3& dq, double r1, double r2, double h, int part, Vec3& n,
                           Vec3& dir) {
  if (part == 1)
    n = {0, 0, -1};
  else if (part == 2)
    n = {0, 0, 1};
  else
    n = normalize(Vec3{l.x, l.y, 0});
  dir = normalize(Vec3{dq.x / r1, dq.y / r2, dq.z / h});
}

/// Span of the infinite elliptic cylinder (x/r1)² + (y/r2)² <= 1 along q + t dq (frame coords).
/// Returns false when the line misses; an infinite span when it runs parallel inside.
bool elliptic_span(const Vec3& q, const Vec3& dq, double r1, double r2, double& t0, double& t1) {
  const double ax = dq.x / r1, ay = dq.y / r2, bx = q.x / r1, by = q.y / r2;
  const double A = ax * ax + ay * ay;
  const double C = bx * bx + by * by - 1;
  if (A == 0) {
    if (C > 0) return false;
    t0 = -kInf;
    t1 = kInf;
    return true;
  }
  return solve_quadratic(A, 2 * (ax * bx + ay * by), C, t0, t1);
}

/// Span of the slab 0 <= z <= h; parts 1 (base) and 2 (top) for the crossings.
bool slab_span(double z, double dz, double h, double& t0, double& t1, int& p0, int& p1) {
  if (dz == 0) {
    if (z < 0 || z > h) return false;
    t0 = -kInf, t1 = kInf, p0 = p1 = 0;
    return true;
  }
  double ta = -z / dz, tb = (h - z) / dz;
  int pa = 1, pb = 2;
  if (ta > tb) std::swap(ta, tb), std::swap(pa, pb);
  t0 = ta, t1 = tb, p0 = pa, p1 = pb;
  return true;
}

/// Closed cylinder span as (t, part) pairs; false when missed.
bool closed_cylinder_span(const CylinderFrame& f, double r1, double r2, const Vec3& o, const Vec3& d, double& tin,
                          double& tout, int& pin, int& pout) {
  const Vec3 q = f.to_frame(o), dq = f.dir_to_frame(d);
  double c0, c1, s0, s1;
  int sp0, sp1;
  if (!elliptic_span(q, dq, r1, r2, c0, c1)) return false;
  if (!slab_span(q.z, dq.z, f.height, s0, s1, sp0, sp1)) return false;
  tin = c0, pin = 0;
  if (s0 > tin) tin = s0, pin = sp0;
  tout = c1, pout = 0;
  if (s1 < tout) tout = s1, pout = sp1;
  return tin <= tout && std::isfinite(tin) && std::isfinite(tout);
}

Bounds3 cylinder_bounds(const CylinderFrame& f, double r1, double r2) {
  Bounds3 b;
  for (int k = 0; k < 8; ++k) {
    const double x = (k & 1) ? r1 : -r1, y = (k & 2) ? r2 : -r2, z = (k & 4) ? f.height : 0.0;
    b.expand(f.base + f.from_frame_dir({x, y, z}));
  }
  return b;
}
}  // namespace

Cylinder::Cylinder(const Vec3& base, const Vec3& top, double r1, double r2) : frame(base, top), r1(r1), r2(r2) {}

void Cylinder::local_spans(const Vec3& o, const Vec3& d, SpanList& out) const {
  double tin, tout;
  int pin, pout;
  if (!closed_cylinder_span(frame, r1, r2, o, d, tin, tout, pin, pout)) return;
  out.push({make_crossing(tin, this, o, d, pin), make_crossing(tout, this, o, d, pout)});
}

Bounds3 Cylinder::local_bounds() const { return cylinder_bounds(frame, r1, r2); }

Vec3 Cylinder::local_normal(const Vec3& p, int part) const {
  if (part == 1) return -frame.ez;
  if (part == 2) return frame.ez;
  const Vec3 q = frame.to_frame(p);
  return normalize(frame.from_frame_dir({q.x / (r1 * r1), q.y / (r2 * r2), 0}));
}

void Cylinder::uv(const Vec3& p, int part, double& u, double& v) const {
  const Vec3 q = frame.to_frame(p);
  unit_cylinder_uv({q.x / r1, q.y / r2, q.z / frame.height}, part != 0, u, v);
}

void Cylinder::shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const {
  const Vec3 q = frame.to_frame(p);
  unit_cylinder_shading({q.x / r1, q.y / r2, q.z / frame.height}, frame.dir_to_frame(d), r1, r2, frame.height, part, n,
                        dir);
}

Ring::Ring(const Vec3& base, const Vec3& top, double r1, double r2, double ri1, double ri2)
    : frame(base, top), r1(r1), r2(r2), ri1(ri1), ri2(ri2) {}

void Ring::local_spans(const Vec3& o, const Vec3& d, SpanList& out) const {
  double tin, tout;
  int pin, pout;
  if (!closed_cylinder_span(frame, r1, r2, o, d, tin, tout, pin, pout)) return;
  // Subtract the infinite inner cylinder (its caps would coincide with the outer caps).
  double c0, c1;
  const Vec3 q = frame.to_frame(o), dq = frame.dir_to_frame(d);
  if (!elliptic_span(q, dq, ri1, ri2, c0, c1) || c1 <= tin || c0 >= tout) {
    out.push({make_crossing(tin, this, o, d, pin), make_crossing(tout, this, o, d, pout)});
    return;
  }
  if (tin < c0) out.push({make_crossing(tin, this, o, d, pin), make_crossing(c0, this, o, d, 3)});
  if (c1 < tout) out.push({make_crossing(c1, this, o, d, 3), make_crossing(tout, this, o, d, pout)});
}

Bounds3 Ring::local_bounds() const { return cylinder_bounds(frame, r1, r2); }

Vec3 Ring::local_normal(const Vec3& p, int part) const {
  if (part == 1) return -frame.ez;
  if (part == 2) return frame.ez;
  const Vec3 q = frame.to_frame(p);
  if (part == 3) return -normalize(frame.from_frame_dir({q.x / (ri1 * ri1), q.y / (ri2 * ri2), 0}));
  return normalize(frame.from_frame_dir({q.x / (r1 * r1), q.y / (r2 * r2), 0}));
}

void Ring::uv(const Vec3& p, int part, double& u, double& v) const {
  const Vec3 q = frame.to_frame(p);
  const double ra = part == 3 ? ri1 : r1, rb = part == 3 ? ri2 : r2;
  unit_cylinder_uv({q.x / ra, q.y / rb, q.z / frame.height}, part == 1 || part == 2, u, v);
}

void Ring::shading_frame(const Vec3& p, const Vec3& d, int part, Vec3& n, Vec3& dir) const {
  const Vec3 q = frame.to_frame(p);
  const double ra = part == 3 ? ri1 : r1, rb = part == 3 ? ri2 : r2;
  // The inner side in the unit frame of the inner cylinder, its normal towards the axis.
  unit_cylinder_shading({q.x / ra, q.y / rb, q.z / frame.height}, frame.dir_to_frame(d), ra, rb, frame.height,
                        part == 3 ? 0 : part, n, dir);
  if (part == 3) n = -n;
}

// ---- planar -------------------------------------------------------------------------------------

bool PlanarPrimitive::intersect(const Segment& seg, Hit& hit) const {
  if (seg.chart0 != chart || seg.chart1 != chart) return false;
  const Vec3 o = transformed ? to_local.point(seg.p0) : seg.p0;
  const Vec3 d = (transformed ? to_local.point(seg.p1) : seg.p1) - o;
  double t, u, v;
  Vec3 n;
  if (!local_intersect(o, d, std::min(1.0, hit.s), t, n, u, v)) return false;
  const Vec3 dw = seg.p1 - seg.p0;
  hit.s = t;
  hit.point = seg.p0 + t * dw;
  hit.ray_dir = normalize(dw);
  // GeoViS GvsPlanarSurf: the plane's normal and the ray's direction in the surface's own frame.
  hit.shade_normal = normalize(n);
  hit.shade_dir = normalize(d);
  n = transformed ? normalize(to_local.transposed_dir(n)) : hit.shade_normal;
  hit.normal = dot(n, hit.ray_dir) > 0 ? -n : n;  // two-sided: face the incoming ray
  hit.u = u;
  hit.v = v;
  hit.shader = shader;
  hit.object_id = object_id;
  hit.time = seg.x0[0] + t * (seg.x1[0] - seg.x0[0]);
  hit.emitter_u = Vec4{{0, 0, 0, 0}};
  hit.keplerian = keplerian_disk;
  hit.part = 0;
  return true;
}

Bounds3 PlanarPrimitive::bounds() const { return transformed ? to_parent.bounds(local_bounds()) : local_bounds(); }

PlaneRing::PlaneRing(const Vec3& c, const Vec3& n, double rin, double rout)
    : center(c), normal(normalize(n)), rin(rin), rout(rout) {
  const Vec3 h = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  e1 = normalize(h - dot(h, normal) * normal);
  e2 = cross(normal, e1);
}

bool PlaneRing::local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                                double& v) const {
  const double denom = dot(normal, d);
  if (denom == 0) return false;
  t = dot(normal, center - o) / denom;
  if (!(t >= 0 && t < tmax)) return false;
  const Vec3 r = o + t * d - center;
  const double x = dot(r, e1), y = dot(r, e2);
  const double rho = std::hypot(x, y);
  if (rho < rin || rho > rout) return false;
  n = normal;
  u = rout > rin ? (rho - rin) / (rout - rin) : 0.0;
  v = std::atan2(r.y, r.x) / kTwoPi + 0.5;
  return true;
}

Bounds3 PlaneRing::local_bounds() const {
  Bounds3 b;
  for (int k = 0; k < 4; ++k) b.expand(center + ((k & 1) ? rout : -rout) * e1 + ((k & 2) ? rout : -rout) * e2);
  return b;
}

double PlaneRing::inner_radius() const {
  const double box = bounds().distance_from_origin();
  if (transformed) return box;
  const double cn = dot(center, normal);
  const double in_plane = std::max(0.0, rin - norm(center - cn * normal));
  return std::max(box, std::sqrt(cn * cn + in_plane * in_plane));
}

bool segment_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double tmax, double& t,
                      double& b1, double& b2, bool parallelogram) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 pv = cross(d, e2);
  const double det = dot(e1, pv);
  if (det == 0) return false;
  const double inv = 1.0 / det;
  const Vec3 tv = o - a;
  b1 = dot(tv, pv) * inv;
  if (b1 < 0 || b1 > 1) return false;
  const Vec3 qv = cross(tv, e1);
  b2 = dot(d, qv) * inv;
  if (b2 < 0 || (parallelogram ? b2 > 1 : b1 + b2 > 1)) return false;
  t = dot(e2, qv) * inv;
  return t >= 0 && t < tmax;
}

bool Triangle::local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                               double& v) const {
  if (!segment_triangle(o, d, p1, p2, p3, tmax, t, u, v)) return false;
  n = cross(p2 - p1, p3 - p1);
  return true;
}

Bounds3 Triangle::local_bounds() const {
  Bounds3 b;
  b.expand(p1), b.expand(p2), b.expand(p3);
  return b;
}

bool Parallelogram::local_intersect(const Vec3& o, const Vec3& d, double tmax, double& t, Vec3& n, double& u,
                                    double& v) const {
  if (!segment_triangle(o, d, p1, p2, p3, tmax, t, u, v, true)) return false;
  n = cross(p2 - p1, p3 - p1);
  return true;
}

Bounds3 Parallelogram::local_bounds() const {
  Bounds3 b;
  b.expand(p1), b.expand(p2), b.expand(p3), b.expand(p2 + p3 - p1);
  return b;
}

// ---- registration (docs/geovis-catalogue.md §4; keys and defaults of GeoViS Parser/parse_*.cpp) ----------

namespace {

using T = ParamType;

const TypeRegistrar<ObjectType> ellipsoid{
    {{"solid-ellipsoid",
      {},
      "an ellipsoid (sphere)",
      primitive_keys_and(
          {{"center", T::Vec3, "centre", false, false, std::vector<double>{0, 0, 0}},
           {"axlen", T::Vec3, "semi-axes", false, false, std::vector<double>{1, 1, 1}, ParamRange::positive()}}),
      {"axlen", "transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       return finish_primitive(keys, ctx,
                               std::make_shared<Ellipsoid>(vec3_key(keys, "center"), vec3_key(keys, "axlen")));
     }}};

const TypeRegistrar<ObjectType> background{
    {{"solid-background", {}, "the sky: a textured sphere at coordinate radius", primitive_keys(false)},
     [](const ParamReader& keys, BuildContext& ctx) {
       return finish_primitive(keys, ctx, std::make_shared<Ellipsoid>(Vec3{0, 0, 0}, Vec3{1, 1, 1}));
     }}};

const TypeRegistrar<ObjectType> box{
    {{"solid-box",
      {},
      "a box",
      primitive_keys_and({{"cornerll", T::Vec3, "first corner", true}, {"cornerur", T::Vec3, "opposite corner", true}}),
      {"transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       const Vec3 a = vec3_key(keys, "cornerll"), b = vec3_key(keys, "cornerur");
       for (int i = 0; i < 3; ++i)
         if (a[i] == b[i]) keys.fail("cornerur", "the box has zero extent along axis " + std::to_string(i));
       return finish_primitive(keys, ctx, std::make_shared<Box>(a, b));
     }}};

std::vector<ParamSpec> cylinder_keys() {
  return {{"base", T::Vec3, "centre of the base", true},
          {"top", T::Vec3, "centre of the top", true},
          {"radii", T::Vec2, "the two radii", true, false, {}, ParamRange::positive()}};
}

const TypeRegistrar<ObjectType> cylinder{
    {{"solid-cylinder", {}, "a cylinder between base and top", primitive_keys_and(cylinder_keys()), {"transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       const Vec3 base = vec3_key(keys, "base"), top = vec3_key(keys, "top");
       if (norm(top - base) == 0) keys.fail("top", "top equals base: the cylinder has no height");
       const auto r = keys.vector("radii", 2);
       return finish_primitive(keys, ctx, std::make_shared<Cylinder>(base, top, r[0], r[1]));
     }}};

const TypeRegistrar<ObjectType> ring{
    {{"solid-ring",
      {},
      "a thick ring (hollow cylinder)",
      [] {
        auto keys = primitive_keys_and(cylinder_keys());
        keys.push_back({"innerradii", T::Vec2, "inner radii", true, false, {}, ParamRange::positive()});
        return keys;
      }(),
      {"transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       const Vec3 base = vec3_key(keys, "base"), top = vec3_key(keys, "top");
       if (norm(top - base) == 0) keys.fail("top", "top equals base: the cylinder has no height");
       const auto r = keys.vector("radii", 2), ri = keys.vector("innerradii", 2);
       if (!(ri[0] < r[0] && ri[1] < r[1])) keys.fail("innerradii", "inner radii must be smaller than the radii");
       return finish_primitive(keys, ctx, std::make_shared<Ring>(base, top, r[0], r[1], ri[0], ri[1]));
     }}};

const TypeRegistrar<ObjectType> plane_ring{
    {{"plane-ring",
      {},
      "a flat ring (disk with a hole)",
      primitive_keys_and(
          {{"center", T::Vec3, "centre", false, false, std::vector<double>{0, 0, 0}},
           {"normal", T::Vec3, "normal", false, false, std::vector<double>{0, 0, 1}},
           {"rout", T::Number, "outer radius", true, false, {}, ParamRange::positive()},
           {"rin", T::Number, "inner radius (< rout)", false, false, 0.0, ParamRange::non_negative()},
           {"emitter", T::String,
            "geovis: velocity of the emitting matter for 1+z: \"rest\" (at rest in the natural frame) or "
            "\"keplerian\" (thin disk on circular geodesics turning in +phi; spherical coordinates, centre 0, "
            "normal along z)",
            false, false, std::string("rest")}}),
      {"transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       const Vec3 n = vec3_key(keys, "normal");
       if (norm(n) == 0) keys.fail("normal", "expected a non-zero normal vector");
       const double rout = keys.number("rout"), rin = keys.number("rin");
       if (!(rin < rout)) keys.fail("rin", "expected 0 <= rin < rout, found rin = " + Value(rin).describe());
       const Vec3 center = vec3_key(keys, "center");
       auto ring = std::make_shared<PlaneRing>(center, n, rin, rout);
       if (keys.choice("emitter", {"rest", "keplerian"}, "emitter velocity") == "keplerian") {
         // circular_orbit_velocity needs the equatorial plane of spherical-like coordinates.
         if (!ctx.metric || ctx.metric->info().coord_type != CoordType::Spherical)
           keys.fail("emitter", "\"keplerian\" needs a metric in spherical coordinates (t, r, theta, phi)" +
                                    (ctx.metric ? std::string(", found ") + ctx.metric->name() : std::string()));
         if (norm(center) != 0 || n.x != 0 || n.y != 0 || keys.has("transform"))
           keys.fail("emitter",
                     "\"keplerian\" needs a ring in the equatorial plane: centre #(0 0 0), normal along z, "
                     "no transform");
         ring->keplerian_disk = true;
       }
       return finish_primitive(keys, ctx, ring);
     }}};

std::vector<ParamSpec> three_points() {
  return {{"p1", T::Vec3, "corner", true}, {"p2", T::Vec3, "corner", true}, {"p3", T::Vec3, "corner", true}};
}

/// p1, p2, p3 of a flat shape; collinear points are a SceneError.
std::array<Vec3, 3> non_collinear_points(const ParamReader& keys) {
  const Vec3 p1 = vec3_key(keys, "p1"), p2 = vec3_key(keys, "p2"), p3 = vec3_key(keys, "p3");
  if (norm(cross(p2 - p1, p3 - p1)) == 0) keys.fail("p3", "the three points are collinear");
  return {p1, p2, p3};
}

const TypeRegistrar<ObjectType> triangle{
    {{"plane-triangle", {}, "a triangle", primitive_keys_and(three_points()), {"transform"}},
     [](const ParamReader& keys, BuildContext& ctx) {
       const auto p = non_collinear_points(keys);
       return finish_primitive(keys, ctx, std::make_shared<Triangle>(p[0], p[1], p[2]));
     }}};

const TypeRegistrar<ObjectType> parallelogram{{{"plane-parallelogram",
                                                {},
                                                "a parallelogram with corners p1, p2, p3 and p2 + p3 - p1",
                                                primitive_keys_and(three_points()),
                                                {"transform"},
                                                true},
                                               [](const ParamReader& keys, BuildContext& ctx) {
                                                 const auto p = non_collinear_points(keys);
                                                 return finish_primitive(
                                                     keys, ctx, std::make_shared<Parallelogram>(p[0], p[1], p[2]));
                                               }}};

}  // namespace

}  // namespace geovis
