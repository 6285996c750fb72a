#version 300 es
// Depth only (the garden's shadow map); the ivy not yet grown in the year shown (vBirth over
// uYear: the year scrubber) casts nothing.
precision highp float;

in float vBirth;
uniform float uYear;

void main() {
  if (vBirth > uYear + 0.5) discard;
}
