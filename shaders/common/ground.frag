#version 300 es
// Grassy ground fading into the background colour, in the sun's shadow map (shadow.glsl) where a
// layer casts one, else with a soft stand-in shadow under the crown (uBlob).
precision highp float;

in vec2 vGround;
in vec4 vShadow;

uniform vec3 uCenter;        // tree base (x, z used)
uniform float uExtent;       // half-size of the plane
uniform float uShadowRadius; // crown radius, metres
uniform vec2 uShadowOffset;  // crown shadow centre minus tree base: cast away from the sun
uniform vec3 uBackground;
uniform float uBlob;         // strength of the stand-in crown shadow (0 with a shadow map or none)

out vec4 outColor;

#include "shadow.glsl"

void main() {
  vec2 d = vGround - uCenter.xz;
  float r = length(d);
  float rs = length(d - uShadowOffset);
  vec3 grass = vec3(0.62, 0.63, 0.50);  // dry meadow, distinct from the leaves
  // Faint 1 m grid so that scale and orbiting read clearly.
  vec2 cell = abs(fract(vGround) - 0.5);
  float line = smoothstep(0.485, 0.5, max(cell.x, cell.y));
  grass *= 1.0 - 0.08 * line;
  float shadow = 1.0 - uBlob * exp(-pow(rs / max(uShadowRadius, 0.05), 2.0) * 1.6);
  shadow *= mix(0.5, 1.0, sunVisibility(vShadow));  // the sky's light only, in the sun's shadow
  vec3 color = grass * shadow;
  float fade = smoothstep(uExtent * 0.45, uExtent * 0.98, r);
  outColor = vec4(mix(color, uBackground, fade), 1.0);
}
