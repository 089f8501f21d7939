#include "render/csg.h"

#include <algorithm>

namespace geovis {

namespace {
/// Appends a span, merging it with the last one when they touch or overlap (union semantics).
void push_merge(SpanList& out, const Span& s) {
  if (out.n > 0 && s.in.t <= out.s[out.n - 1].out.t) {
    if (s.out.t > out.s[out.n - 1].out.t) out.s[out.n - 1].out = s.out;
    return;
  }
  out.push(s);
}
Crossing flipped(Crossing c) {
  c.flip = !c.flip;
  return c;
}
}  // namespace

void csg_union(const SpanList& a, const SpanList& b, SpanList& out) {
  out.n = 0;
  int i = 0, j = 0;
  while (i < a.n || j < b.n) {
    const bool take_a = j >= b.n || (i < a.n && a.s[i].in.t <= b.s[j].in.t);
    push_merge(out, take_a ? a.s[i++] : b.s[j++]);
  }
}

void csg_intersection(const SpanList& a, const SpanList& b, SpanList& out) {
  out.n = 0;
  int i = 0, j = 0;
  while (i < a.n && j < b.n) {
    const Span& x = a.s[i];
    const Span& y = b.s[j];
    const Crossing& in = x.in.t >= y.in.t ? x.in : y.in;
    const Crossing& o = x.out.t <= y.out.t ? x.out : y.out;
    if (in.t < o.t) out.push({in, o});
    if (x.out.t < y.out.t) ++i;
    else ++j;
  }
}

void csg_difference(const SpanList& a, const SpanList& b, SpanList& out) {
  out.n = 0;
  for (int i = 0; i < a.n; ++i) {
    Crossing cur_in = a.s[i].in;
    const Crossing cur_out = a.s[i].out;
    bool open = true;  // [cur_in, cur_out] still has a remainder to emit
    for (int j = 0; j < b.n && open; ++j) {
      const Span& y = b.s[j];
      if (y.out.t <= cur_in.t) continue;   // removed part lies before
      if (y.in.t >= cur_out.t) break;      // and all further ones after
      if (y.in.t > cur_in.t) out.push({cur_in, flipped(y.in)});
      if (y.out.t < cur_out.t) cur_in = flipped(y.out);
      else open = false;
    }
    if (open) out.push({cur_in, cur_out});
  }
}

CsgObject::CsgObject(CsgOp op, std::shared_ptr<const Solid> a, std::shared_ptr<const Solid> b)
    : op(op), first(std::move(a)), second(std::move(b)) {
  chart = first->chart;
}

void CsgObject::spans(const Vec3& a, const Vec3& d, SpanList& out) const {
  SpanList sa, sb;
  first->spans(a, d, sa);
  if (sa.n == 0 && op != CsgOp::Union) {
    out.n = 0;
    return;
  }
  second->spans(a, d, sb);
  switch (op) {
    case CsgOp::Difference: csg_difference(sa, sb, out); break;
    case CsgOp::Union: csg_union(sa, sb, out); break;
    case CsgOp::Intersection: csg_intersection(sa, sb, out); break;
  }
}

Bounds3 CsgObject::bounds() const {
  const Bounds3 ba = first->bounds();
  if (op == CsgOp::Difference) return ba;
  const Bounds3 bb = second->bounds();
  if (op == CsgOp::Union) {
    Bounds3 r = ba;
    r.expand(bb);
    return r;
  }
  Bounds3 r;
  r.lo = {std::max(ba.lo.x, bb.lo.x), std::max(ba.lo.y, bb.lo.y), std::max(ba.lo.z, bb.lo.z)};
  r.hi = {std::min(ba.hi.x, bb.hi.x), std::min(ba.hi.y, bb.hi.y), std::min(ba.hi.z, bb.hi.z)};
  return r;
}

}  // namespace geovis
