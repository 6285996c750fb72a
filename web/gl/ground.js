// The ground plane (shaders/common/ground.*): a square of half-size `extent` at y = 0 fading into
// the background, receiving the sun's shadow map (web/gl/shadow_map.js) where a layer casts one,
// else a soft stand-in shadow under the crown. Shared by every study's view.
// Does not: cast shadows or follow a terrain (the terrain study draws its own surface).
import { BACKGROUND } from './context.js';

// The ground's draw options under a footprint {center, extent, shadowRadius, crownHeight,
// shadowOffset?} (metres): the crown's shadow falls away from the sun (its centre projected along
// `light`, the unit direction towards the sun), or at the footprint's own shadowOffset ([x, z] from
// the centre: the grove, which has no single crown, moves it far away). One rule for a renderer
// alone and for a Frame of layers.
export function groundUnder(footprint, light) {
  const reach = (footprint.crownHeight || 0) / Math.max(light[1], 0.25);
  return { center: footprint.center, extent: footprint.extent, shadowRadius: footprint.shadowRadius,
    shadowOffset: footprint.shadowOffset || [-light[0] * reach, -light[2] * reach] };
}

export class Ground {
  // program: the linked ground program ({program, uniforms}).
  constructor(gl, program) {
    this.gl = gl;
    this.program = program;
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.corners = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, this.corners);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  // Draws the ground (2 triangles, 1 draw call) pushed back by a polygon offset.
  // center: [x, y, z] m; shadowOffset: [x, z] m of the stand-in shadow's centre from `center`;
  // blob: its strength (0: none). map: the frame's ShadowMap (its texture is always bound for the
  // sampler) and sun: {matrix, texel} when the ground reads it, else null.
  draw(viewProjection, { center, extent, shadowRadius, shadowOffset, blob = 0.45 }, map = null, sun = null) {
    const gl = this.gl, g = this.program;
    gl.useProgram(g.program);
    if (map) map.bindFor(g, sun);
    else gl.uniform1f(g.uniforms.uShadowOn, 0);
    gl.uniform1f(g.uniforms.uBlob, blob);
    gl.uniformMatrix4fv(g.uniforms.uViewProjection, false, viewProjection);
    gl.uniform3fv(g.uniforms.uCenter, center);
    gl.uniform1f(g.uniforms.uExtent, extent);
    gl.uniform1f(g.uniforms.uShadowRadius, shadowRadius);
    gl.uniform2fv(g.uniforms.uShadowOffset, shadowOffset);
    gl.uniform3fv(g.uniforms.uBackground, BACKGROUND);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    gl.bindVertexArray(null);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    return { triangles: 2, drawCalls: 1 };
  }

  dispose() {
    this.gl.deleteVertexArray(this.vao);
    this.gl.deleteBuffer(this.corners);
  }
}
