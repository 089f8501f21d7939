// The post-processing shaders of `geovis post` (src/render/post.cpp) as GLSL: one value per
// pixel from the data file's channels. Formulas as there:
//   redshift  z (1+z, paper eq. 15)        time  x0          lensing  jac.mu        stop  stop code
//   disk-flux F/F0 = Page–Thorne flux at R = r/r_s (paper eq. 16, Page & Thorne 1974, a = 0) over
//             (1+z)^4 (paper §5); no value inside R = 3 or without 1+z.

/** Which channels a mode reads: [a, b] (b only for disk-flux). */
export const shaderChannels: Record<string, string[]> = {
  redshift: ['z'],
  time: ['x0'],
  lensing: ['jac.mu'],
  stop: ['stop'],
  'disk-flux': ['x1', 'z'],
};

/** Mode numbers of the value pass. */
export const modeOf: Record<string, number> = { channel: 0, redshift: 0, time: 0, lensing: 0, stop: 0, 'disk-flux': 1 };

export const valueFragmentShader = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D uA;  // R32F, texel (x, y) = pixel x, row y (row 0 = top)
uniform highp sampler2D uB;
uniform int uMode;           // 0: the value of channel A; 1: disk-flux from A = x1 (r), B = z (1+z)
uniform float uMass;
out vec4 outValue;

float nan() { return uintBitsToFloat(0x7fc00000u); }
bool isNaN(float v) { return (floatBitsToUint(v) & 0x7fffffffu) > 0x7f800000u; }

// Paper eq. 16, R = r/r_s: F/F0 = (sqrt R - sqrt 3 + sqrt(3/2)/2 ln(...)) / ((R - 3/2) R^(5/2)).
float pageThorneFlux(float R) {
  if (!(R > 3.0)) return 0.0;
  float s32 = sqrt(1.5), s3 = sqrt(3.0), sR = sqrt(R);
  float logTerm = log((sR + s32) / (sR - s32) * (s3 - s32) / (s3 + s32));
  return (sR - s3 + 0.5 * s32 * logTerm) / ((R - 1.5) * pow(R, 2.5));
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float a = texelFetch(uA, p, 0).r;
  if (uMode == 0) { outValue = vec4(a, 0.0, 0.0, 1.0); return; }
  float opz = texelFetch(uB, p, 0).r;
  float R = a / (2.0 * uMass);
  if (isNaN(R) || isNaN(opz) || !(R > 3.0) || !(opz > 0.0)) { outValue = vec4(nan(), 0.0, 0.0, 1.0); return; }
  outValue = vec4(pageThorneFlux(R) / pow(opz, 4.0), 0.0, 0.0, 1.0);
}
`;
