// The sun's shadow map (web/gl/shadow_map.js) read by a receiver's fragment shader (web/gl/program.js
// inserts it where a shader says #include "../common/shadow.glsl", relative to that shader):
// 2 × 2 taps, 1.5 texels apart, of a hardware-compared, linearly filtered depth texture (each tap
// itself a 2 × 2 PCF: a 4 × 4-texel footprint in 4 reads, for SwiftShader, the CPU WebGL, where
// every fragment's reads cost); 1 lit, 0 in shadow.
// vShadow: the fragment in the sun's clip space (its vertex shader computes it, normal-offset).
uniform highp sampler2DShadow uShadowMap;
uniform float uShadowOn;     // 0: no map (every fragment lit)
uniform float uShadowTexel;  // one texel of the map in its uv units (1 / size)

float sunVisibility(vec4 shadowClip) {
  if (uShadowOn < 0.5) return 1.0;
  vec3 p = shadowClip.xyz / shadowClip.w * 0.5 + 0.5;
  if (p.x < 0.0 || p.y < 0.0 || p.x > 1.0 || p.y > 1.0) return 1.0;  // outside the casters' box
  float z = min(p.z, 1.0);
  vec2 d = vec2(0.75 * uShadowTexel);
  float lit = texture(uShadowMap, vec3(p.xy + vec2(-d.x, -d.y), z)) + texture(uShadowMap, vec3(p.xy + vec2(d.x, -d.y), z)) +
              texture(uShadowMap, vec3(p.xy + vec2(-d.x, d.y), z)) + texture(uShadowMap, vec3(p.xy + vec2(d.x, d.y), z));
  return 0.25 * lit;
}
