// WebGL2 renderer: bark tubes, double-sided leaves and flowers, and a ground plane.
// Shaders (GLSL ES 3.00) are fetched at runtime from /shaders/.

const BACKGROUND = [0.86, 0.90, 0.94];
const NONE = 0xffffffff;  // "no branch" for the branch-id attribute and the selection

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
    this.setSun(60, 0);
    this.lastFrame = { triangles: 0, drawCalls: 0, cpuMs: 0 };
  }

  // The light model's sun (the core's convention): elevation and azimuth in degrees, y up, azimuth
  // measured from +x towards +z; direction = (cos el cos az, sin el, cos el sin az), towards the sun.
  setSun(elevationDeg, azimuthDeg) {
    const el = (Number(elevationDeg) * Math.PI) / 180, az = (Number(azimuthDeg) * Math.PI) / 180;
    if (!Number.isFinite(el) || !Number.isFinite(az)) return;
    this.light = normalize([Math.cos(el) * Math.cos(az), Math.sin(el), Math.cos(el) * Math.sin(az)]);
  }

  async init(shaderBase = new URL('../shaders/', import.meta.url).href) {
    const [treeVert, treeFrag, groundVert, groundFrag, pickVert, pickFrag] = await Promise.all(
      ['tree.vert', 'tree.frag', 'ground.vert', 'ground.frag', 'pick.vert', 'pick.frag']
        .map((f) => fetchText(new URL(f, shaderBase).href)));
    const gl = this.gl;
    this.treeProgram = link(gl, treeVert, treeFrag, 'tree');
    this.pickProgram = link(gl, pickVert, pickFrag, 'pick');
    this.selected = NONE;
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

  // mesh: {bark|leaves|flowers: {positions, normals, indices}} as ArrayBuffers (bark also has
  // branchIds: Uint32 per vertex); bounds in metres.
  setTree(mesh, bounds) {
    const gl = this.gl;
    for (const part of Object.values(this.parts)) {
      gl.deleteVertexArray(part.vao);
      part.buffers.forEach((b) => gl.deleteBuffer(b));
    }
    this.parts = {};
    this.highlight = null;
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
      if (data.branchIds && data.branchIds.byteLength === data.positions.byteLength / 3) {
        const buffer = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
        gl.bufferData(gl.ARRAY_BUFFER, data.branchIds, gl.STATIC_DRAW);
        gl.enableVertexAttribArray(2);
        gl.vertexAttribIPointer(2, 1, gl.UNSIGNED_INT, 0, 0);
        buffers.push(buffer);
        // Selection highlight per vertex (select() fills it).
        this.branchIds = new Uint32Array(data.branchIds);
        this.branchParents = new Int32Array(data.branchParents || new ArrayBuffer(0));
        this.highlight = new Float32Array(this.branchIds.length);
        this.highlightBuffer = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, this.highlightBuffer);
        gl.bufferData(gl.ARRAY_BUFFER, this.highlight, gl.DYNAMIC_DRAW);
        gl.enableVertexAttribArray(3);
        gl.vertexAttribPointer(3, 1, gl.FLOAT, false, 0, 0);
        buffers.push(this.highlightBuffer);
      } else {
        gl.disableVertexAttribArray(2);
      }
      const index = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, index);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, data.indices, gl.STATIC_DRAW);
      buffers.push(index);
      gl.bindVertexArray(null);
      this.parts[name] = { vao, buffers, count: data.indices.byteLength / 4, picking: Boolean(data.branchIds) };
    }
    const min = bounds.min, max = bounds.max;
    this.center = [(min[0] + max[0]) / 2, 0, (min[2] + max[2]) / 2];
    this.crownHeight = Math.max(0, 0.6 * max[1]);
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
    const start = performance.now();
    let triangles = 0, drawCalls = 0;
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
    // The crown's shadow falls away from the sun (crown centre projected along the light).
    const reach = (this.crownHeight || 0) / Math.max(this.light[1], 0.25);
    gl.uniform2fv(g.uniforms.uShadowOffset, [-this.light[0] * reach, -this.light[2] * reach]);
    gl.uniform3fv(g.uniforms.uBackground, BACKGROUND);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.bindVertexArray(this.groundVao);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    triangles += 2;
    drawCalls += 1;
    gl.disable(gl.POLYGON_OFFSET_FILL);

    const t = this.treeProgram;
    gl.useProgram(t.program);
    gl.uniformMatrix4fv(t.uniforms.uViewProjection, false, viewProjection);
    gl.uniform3fv(t.uniforms.uLightDirection, this.light);
    gl.uniform3fv(t.uniforms.uCameraPosition, camera.position());
    gl.vertexAttrib1f(3, 0);  // no highlight on parts without branch ids
    for (const [name, part] of Object.entries(this.parts)) {
      const look = PARTS[name];
      gl.uniform3fv(t.uniforms.uColor, look.color);
      gl.uniform3fv(t.uniforms.uColorVariation, look.variation);
      gl.uniform1f(t.uniforms.uDoubleSided, look.doubleSided);
      gl.uniform1f(t.uniforms.uSpecular, look.specular);
      gl.uniform1f(t.uniforms.uXray, 0);
      gl.bindVertexArray(part.vao);
      gl.drawElements(gl.TRIANGLES, part.count, gl.UNSIGNED_INT, 0);
      triangles += part.count / 3;
      drawCalls += 1;
    }
    // The selection once more, faintly through everything, so a branch behind leaves shows.
    if (this.selected !== NONE && this.parts.bark) {
      gl.uniform1f(t.uniforms.uXray, 1);
      gl.uniform3fv(t.uniforms.uColor, PARTS.bark.color);
      gl.uniform1f(t.uniforms.uDoubleSided, 0);
      gl.disable(gl.DEPTH_TEST);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      gl.bindVertexArray(this.parts.bark.vao);
      gl.drawElements(gl.TRIANGLES, this.parts.bark.count, gl.UNSIGNED_INT, 0);
      triangles += this.parts.bark.count / 3;
      drawCalls += 1;
      gl.disable(gl.BLEND);
      gl.enable(gl.DEPTH_TEST);
    }
    gl.bindVertexArray(null);
    // What this frame drew (from the index counts drawn) and the CPU time of this call; GPU time is
    // not measured (no timer queries on SwiftShader).
    this.lastFrame = { triangles, drawCalls, cpuMs: performance.now() - start };
    return this.lastFrame;
  }

  // Highlights one branch (id) and, fainter, every branch growing from it (what a cut removes);
  // null clears the highlight.
  select(id) {
    this.selected = Number.isInteger(id) && id >= 0 ? id : NONE;
    if (!this.highlight || !this.parts.bark) return;
    const parents = this.branchParents;
    const mark = new Float32Array(parents.length);  // per branch: 0, 0.5 above, 1 selected
    if (this.selected !== NONE && this.selected < parents.length) {
      mark[this.selected] = 1;
      // Parents come before their children (ids grow with time), so one pass in id order suffices.
      for (let b = this.selected + 1; b < parents.length; ++b) {
        const p = parents[b];
        if (p >= 0 && mark[p] > 0) mark[b] = 0.5;
      }
    }
    for (let v = 0; v < this.branchIds.length; ++v) this.highlight[v] = mark[this.branchIds[v]] || 0;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.highlightBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.highlight);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
  }

  // Branch id under canvas pixel (x, y) in CSS pixels from the top left, or null: draws the bark's
  // branch ids into an offscreen framebuffer and reads a small square around the point (the
  // nearest hit wins, so thin twigs can be clicked).
  pick(camera, x, y, radius = 4) {
    const gl = this.gl;
    const bark = this.parts.bark;
    if (!this.pickProgram || !bark || !bark.picking) return null;
    this.resize();
    const w = this.canvas.width, h = this.canvas.height;
    if (!this.pickTarget || this.pickTarget.w !== w || this.pickTarget.h !== h) {
      if (this.pickTarget) {
        gl.deleteFramebuffer(this.pickTarget.fb);
        gl.deleteRenderbuffer(this.pickTarget.color);
        gl.deleteRenderbuffer(this.pickTarget.depth);
      }
      const fb = gl.createFramebuffer();
      const color = gl.createRenderbuffer();
      const depth = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, color);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, w, h);
      gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, w, h);
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, color);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
      this.pickTarget = { fb, color, depth, w, h };
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.pickTarget.fb);
    gl.viewport(0, 0, w, h);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.disable(gl.DITHER);  // ids must come back bit-exact
    const p = this.pickProgram;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, camera.viewProjection(w / h));
    gl.bindVertexArray(bark.vao);
    gl.drawElements(gl.TRIANGLES, bark.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);

    const scale = w / Math.max(1, this.canvas.clientWidth);
    const px = Math.round(x * scale), py = Math.round(h - 1 - y * scale);
    const r = Math.round(radius * scale);
    const x0 = Math.max(0, px - r), y0 = Math.max(0, py - r);
    const x1 = Math.min(w - 1, px + r), y1 = Math.min(h - 1, py + r);
    let best = null, bestDistance = Infinity;
    if (x1 >= x0 && y1 >= y0) {
      const rw = x1 - x0 + 1, rh = y1 - y0 + 1;
      const data = new Uint8Array(rw * rh * 4);
      gl.readPixels(x0, y0, rw, rh, gl.RGBA, gl.UNSIGNED_BYTE, data);
      for (let j = 0; j < rh; ++j) {
        for (let i = 0; i < rw; ++i) {
          const k = (j * rw + i) * 4;
          const v = data[k] | (data[k + 1] << 8) | (data[k + 2] << 16);
          const d = (x0 + i - px) ** 2 + (y0 + j - py) ** 2;
          if (v > 0 && d < bestDistance) { bestDistance = d; best = v - 1; }
        }
      }
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.enable(gl.DITHER);
    return best;
  }
}

function normalize(v) {
  const l = Math.hypot(v[0], v[1], v[2]);
  return v.map((x) => x / l);
}
