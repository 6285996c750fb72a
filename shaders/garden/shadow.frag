#version 300 es
// Depth only (the garden's shadow map).
precision highp float;

void main() {}
