#include "render/csg.h"

#include <algorithm>

#include "render/local_object.h"
#include "render/object_type.h"

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
    if (x.out.t < y.out.t)
      ++i;
    else
      ++j;
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
      if (y.out.t <= cur_in.t) continue;  // removed part lies before
      if (y.in.t >= cur_out.t) break;     // and all further ones after
      if (y.in.t > cur_in.t) out.push({cur_in, flipped(y.in)});
      if (y.out.t < cur_out.t)
        cur_in = flipped(y.out);
      else
        open = false;
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

double CsgObject::surface_free_radius() const {
  return std::max(inner_radius(), std::min(first->surface_free_radius(), second->surface_free_radius()));
}

// ---- registration (docs/geovis-catalogue.md §4) -------------------------------------------------

namespace {

SceneObjectPtr make_csg(const ParamReader& keys, BuildContext& ctx) {
  const ParamSet& ps = keys.params();
  int type = keys.integer("csgtype");
  if (type == 0) {
    ctx.diagnostics().warn(ps.loc(), ps.command(), "csgtype",
                           "missing or 0: using difference (1), as GeoViS does (valid: 1 difference, 2 union, 3 "
                           "intersection)");
    type = 1;
  }
  if (type < 1 || type > 3)
    ps.fail("csgtype", "expected 1 (difference), 2 (union) or 3 (intersection), found " + std::to_string(type));
  const std::string id1 = ps.get_string("obj1"), id2 = ps.get_string("obj2");
  const SceneObjectPtr& a = ctx.lookup(ctx.objects, id1, ps, "obj1", "object");
  const SceneObjectPtr& b = ctx.lookup(ctx.objects, id2, ps, "obj2", "object");
  auto moving_a = std::dynamic_pointer_cast<const LocalObject>(a);
  auto moving_b = std::dynamic_pointer_cast<const LocalObject>(b);
  SceneObjectPtr sa = a, sb = b;
  if (moving_a || moving_b) {
    // Both solids must move together: the CSG is then built in their common rest frame and
    // moved as a whole.
    if (!moving_a || !moving_b || !moving_a->frame().moving() || !moving_b->frame().moving() ||
        moving_a->frame().motion() != moving_b->frame().motion())
      ps.fail("obj2", "\"" + id1 + "\" and \"" + id2 +
                          "\" must both be solids at rest in coordinates or both move with the same motion");
    sa = moving_a->child();
    sb = moving_b->child();
  }
  auto solid_a = std::dynamic_pointer_cast<const Solid>(sa);
  auto solid_b = std::dynamic_pointer_cast<const Solid>(sb);
  if (!solid_a) ps.fail("obj1", "\"" + id1 + "\" is not a solid (csg-object combines solid-* objects and csg-objects)");
  if (!solid_b) ps.fail("obj2", "\"" + id2 + "\" is not a solid (csg-object combines solid-* objects and csg-objects)");
  auto csg = std::make_shared<CsgObject>(static_cast<CsgOp>(type), solid_a, solid_b);
  csg->id = ps.get_string("id", "");
  if (moving_a) {
    auto moving = std::make_shared<LocalObject>(csg, moving_a->frame());
    moving->id = csg->id;
    moving->chart = csg->chart;
    return moving;
  }
  return csg;
}

// GeoViS lets a per-frame change set a CSG object's transform; ours has none yet (its solids'
// normals are computed in their own parent frame), so such a change is an error, not ignored.
const TypeRegistrar<ObjectType> csg_registrar{
    {{"csg-object",
      {},
      "union, difference or intersection of two solids",
      {{"csgtype", ParamType::Int, "1 difference, 2 union, 3 intersection (0: difference, with a warning)", false,
        false, 0.0},
       {"obj1", ParamType::String, "first solid", true},
       {"obj2", ParamType::String, "second solid", true},
       {"id", ParamType::String, "object id"}}},
     make_csg,
     true}};

}  // namespace

}  // namespace geovis
