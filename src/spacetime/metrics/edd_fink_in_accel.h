// −Γ^μ_{ab} k^a k^b of Schwarzschild in ingoing Eddington–Finkelstein coordinates (the symbols of
// EddFinkIn::christoffel_closed in edd_fink_in.cpp written out), once as a template over the number
// type: edd_fink_in.cpp includes this file once for doubles (the scalar integrator) and once per
// SIMD target for SimdD (spacetime/simd.h, the packet integrator), so both run the same operations
// and give the same bits. No include guard: each inclusion defines the template in the namespace it
// is included in.
template <class T>
GEOVIS_HOT_INLINE void edd_fink_in_accel(double rs, const Vec4T<T>& x, const Vec4T<T>& k, Vec4T<T>& a) {
  const T r = x[1];
  T st, ct;
  sincos_t(x[2], st, ct);
  const T rmrs = r - rs;
  const T ang = k[2] * k[2] + st * st * k[3] * k[3];
  a[0] = -rs / (2.0 * r * r) * k[0] * k[0] + r * ang;
  a[1] = -rs * rmrs / (2.0 * r * r * r) * k[0] * k[0] + rs / (r * r) * k[0] * k[1] + rmrs * ang;
  a[2] = -2.0 / r * k[1] * k[2] + st * ct * k[3] * k[3];
  a[3] = -2.0 / r * k[1] * k[3] - 2.0 * ct / st * k[2] * k[3];
}
