// WebGL2 renderer: bark tubes, double-sided leaves and flowers, and a ground plane.
// Shaders (GLSL ES 3.00) are fetched at runtime from /shaders/.

const BACKGROUND = [0.86, 0.90, 0.94];

const PARTS = {
  bark: { color: [0.36, 0.25, 0.18], variation: [0.04, 0.03, 0.02], doubleSided: 0, specular: 0.03 },
  leaves: { color: [0.30, 0.55, 0.20], variation: [0.10, 0.14, 0.06], doubleSided: 1, specular: 0.05 },
  flowers: { color: [0.98, 0.74, 0.84], variation: [0.02, 0.08, 0.06], doubleSided: 1, specular: 0.08 },
};

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`cannot load ${url} (${response.status})`);
  return response.text();
}

function compile(gl, type, source, name) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(shader);
    gl.deleteShader(shader);
    throw new Error(`shader ${name}: ${log}`);
  }
  return shader;
}

function link(gl, vertexSource, fragmentSource, name) {
  const program = gl.createProgram();
  const vs = compile(gl, gl.VERTEX_SHADER, vertexSource, `${name}.vert`);
  const fs = compile(gl, gl.FRAGMENT_SHADER, fragmentSource, `${name}.frag`);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`program ${name}: ${gl.getProgramInfoLog(program)}`);
  const uniforms = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; ++i) {
    const info = gl.getActiveUniform(program, i);
    uniforms[info.name] = gl.getUniformLocation(program, info.name);
  }
  return { program, uniforms };
}

export class Renderer {
  // Throws an Error with a readable message when WebGL2 is missing.
  constructor(canvas) {
    this.canvas = canvas;
    const gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true, alpha: false });
    if (!gl) throw new Error('WebGL2 is not available in this browser, so the tree cannot be drawn.');
    this.gl = gl;
    this.parts = {};
    this.center = [0, 0, 0];
    this.shadowRadius = 1;
    this.extent = 20;
    this.light = normalize([0.45, 0.8, 0.4]);
  }

  async init(shaderBase = new URL('../shaders/', import.meta.url).href) {
    const [treeVert, treeFrag, groundVert, groundFrag] = await Promise.all(
      ['tree.vert', 'tree.frag', 'ground.vert', 'ground.frag'].map((f) => fetchText(new URL(f, shaderBase).href)));
    const gl = this.gl;
    this.treeProgram = link(gl, treeVert, treeFrag, 'tree');
    this.groundProgram = link(gl, groundVert, groundFrag, 'ground');
    this.groundVao = gl.createVertexArray();
    gl.bindVertexArray(this.groundVao);
    const corners = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, corners);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  // mesh: {bark|leaves|flowers: {positions, normals, indices}} as ArrayBuffers; bounds in metres.
  setTree(mesh, bounds) {
    const gl = this.gl;
    for (const part of Object.values(this.parts)) {
      gl.deleteVertexArray(part.vao);
      part.buffers.forEach((b) => gl.deleteBuffer(b));
    }
    this.parts = {};
    for (const name of Object.keys(PARTS)) {
      const data = mesh[name];
      if (!data || data.indices.byteLength === 0) continue;
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const buffers = [];
      const attribute = (location, bytes) => {
        const buffer = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
        gl.bufferData(gl.ARRAY_BUFFER, bytes, gl.STATIC_DRAW);
        gl.enableVertexAttribArray(location);
        gl.vertexAttribPointer(location, 3, gl.FLOAT, false, 0, 0);
        buffers.push(buffer);
      };
      attribute(0, data.positions);
      attribute(1, data.normals);
      const index = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, index);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, data.indices, gl.STATIC_DRAW);
      buffers.push(index);
      gl.bindVertexArray(null);
      this.parts[name] = { vao, buffers, count: data.indices.byteLength / 4 };
    }
    const min = bounds.min, max = bounds.max;
    this.center = [(min[0] + max[0]) / 2, 0, (min[2] + max[2]) / 2];
    this.shadowRadius = Math.max(0.3, 0.5 * Math.max(max[0] - min[0], max[2] - min[2]));
    this.extent = Math.max(6, 4 * Math.max(max[1] - min[1], this.shadowRadius * 2));
  }

  resize() {
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr));
    const h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
  }

  render(camera) {
    const gl = this.gl;
    if (!this.treeProgram) return;
    this.resize();
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    const viewProjection = camera.viewProjection(this.canvas.width / this.canvas.height);

    const g = this.groundProgram;
    gl.useProgram(g.program);
    gl.uniformMatrix4fv(g.uniforms.uViewProjection, false, viewProjection);
    gl.uniform3fv(g.uniforms.uCenter, this.center);
    gl.uniform1f(g.uniforms.uExtent, this.extent);
    gl.uniform1f(g.uniforms.uShadowRadius, this.shadowRadius);
    gl.uniform3fv(g.uniforms.uBackground, BACKGROUND);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.bindVertexArray(this.groundVao);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    gl.disable(gl.POLYGON_OFFSET_FILL);

    const t = this.treeProgram;
    gl.useProgram(t.program);
    gl.uniformMatrix4fv(t.uniforms.uViewProjection, false, viewProjection);
    gl.uniform3fv(t.uniforms.uLightDirection, this.light);
    gl.uniform3fv(t.uniforms.uCameraPosition, camera.position());
    for (const [name, part] of Object.entries(this.parts)) {
      const look = PARTS[name];
      gl.uniform3fv(t.uniforms.uColor, look.color);
      gl.uniform3fv(t.uniforms.uColorVariation, look.variation);
      gl.uniform1f(t.uniforms.uDoubleSided, look.doubleSided);
      gl.uniform1f(t.uniforms.uSpecular, look.specular);
      gl.bindVertexArray(part.vao);
      gl.drawElements(gl.TRIANGLES, part.count, gl.UNSIGNED_INT, 0);
    }
    gl.bindVertexArray(null);
  }
}

function normalize(v) {
  const l = Math.hypot(v[0], v[1], v[2]);
  return v.map((x) => x / l);
}
