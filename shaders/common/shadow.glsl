// The sun's shadow map (web/gl/shadow_map.js) read by a receiver's fragment shader (web/gl/program.js
// inserts it where a shader says #include "../common/shadow.glsl", relative to that shader):
// 3 × 3 taps of a hardware-compared, linearly filtered depth texture (PCF); 1 lit, 0 in shadow.
// vShadow: the fragment in the sun's clip space (its vertex shader computes it, normal-offset).
uniform highp sampler2DShadow uShadowMap;
uniform float uShadowOn;     // 0: no map (every fragment lit)
uniform float uShadowTexel;  // one texel of the map in its uv units (1 / size)

float sunVisibility(vec4 shadowClip) {
  if (uShadowOn < 0.5) return 1.0;
  vec3 p = shadowClip.xyz / shadowClip.w * 0.5 + 0.5;
  if (p.x < 0.0 || p.y < 0.0 || p.x > 1.0 || p.y > 1.0) return 1.0;  // outside the casters' box
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(uShadowMap, vec3(p.xy + vec2(float(x), float(y)) * 1.5 * uShadowTexel, min(p.z, 1.0)));
  return lit / 9.0;
}
