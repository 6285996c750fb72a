// The garden page's WebGL2 view (shaders/garden/): the ground (tinted by height, or by an overlay:
// the moss's light of its last day, the slope, altitude bands), the objects
// (walls, rocks, stone lanterns) and every planted tree, each distinct tree's mesh uploaded once and
// drawn at all its placements with instancing (as the grove draws its copies), in metres, y up, under
// the frame's camera and sun; the objects and trees cast the sun's shadow into the frame's shadow
// map and everything receives it. Also the ground's height under a point and the ray of a click
// (the page's planting by click). Another garden year (the year scrubber: setYear) swaps the trees'
// meshes and the ground's moss light for that year's and hides the ivy born after it (the objects'
// birth year per vertex against uYear); nothing else is re-uploaded. Blow (web/garden/garden_wind.js):
// setSkin adds the trees' sway skin (joints, weights per vertex; each copy's first pose block) to
// their VAO, setPoses uploads every copy's poses into one pose texture and the shaders skin each
// copy with its own block (shaders/common/skin.glsl); still() draws the grown shape again.
// Simulated bark (the garden's bark 1): setGarden's `barks` (per distinct tree its bark maps, the
// garden .glb's, or null) are uploaded once and bound for that tree's draws, its bark drawn with
// them through the trees' uvs (garden.frag); the other trees keep the procedural brown. A year
// picked keeps them (the bark is run once, on the last year's trunk).
// Hybrid trees (garden_hybrid.js): setFull(mask) draws only the copies the mask keeps in full
// (the others are the grove renderer's cards and lines, another layer), each skinned to its own
// pose block while Blow plays; setFull(null) all of them.
// The ground is drawn through its level of detail (ground_lod.js: far tiles of the grid with fewer of
// its own vertices, no crack), chosen for each frame's eye; lodPx = 0 draws the full grid (a test's A/B).
// A StudyLayer (web/gl/frame.js), a layer of a Frame of fit: false (metres).
// Does not: talk to the worker, know the garden model, or draw the hybrid (card) trees itself.
import { copyOf, floatAttribute, staticBuffer, uintAttribute, viewOf } from '../gl/buffers.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';
import { imageTexture, restPoses, uploadPoses } from '../gl/textures.js';
import { GroundLod, pixelsAtOneMetre } from './ground_lod.js';

const SHADERS = new URL('../../shaders/garden/', import.meta.url).href;
const INSTANCE_BYTES = 16;  // x, y, z, turn (radians)
const POSE_UNIT = 1;       // the texture unit of the sway poses (the shadow map's is 7)
const BARK_UNIT = 2;       // the simulated bark's base colour; its normal map on BARK_UNIT + 1
const GROUND_UNIT = 4;     // the ground's per-vertex normal and moss light (its level of detail)
// The ground's overlays, in garden.frag's uOverlay order.
export const OVERLAYS = ['none', 'moss', 'slope', 'altitude'];

export class GardenRenderer extends StudyLayer {
  constructor(target) {
    super(target, { what: 'the garden', study: 'tree' });
    this.ground = null;   // {vao, buffers, count}
    this.objects = null;  // {vao, buffers, count}
    this.trees = null;    // {vao, buffers, instanceBuffer, groups: [{firstIndex, count, firstInstance, instances}]}
    this.grid = null;     // {n, size, cell, heights: Float32Array, relief}
    this.serial = 0;
    this.overlay = 'none';  // one of OVERLAYS
    this.hasMoss = false;   // the ground carries the moss's light (its moss_S buffer)
    this.year = null;       // the garden year shown (null: the last grown; ivy by its birth year)
    this.swayOn = false;    // the trees skinned to the poses (Blow)
    this.poseSerial = 0;    // poses uploaded since the wind started (the shadow map's key)
    this.barks = [];        // per distinct tree: {colour, normal, digest} textures, or null (procedural)
    this.barkShown = true;  // false: every tree in the procedural brown (a test's A/B of one frame)
    this.lodPx = undefined;  // the ground's level of detail: undefined its LOD_PX, 0 the full grid
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS, {
      mesh: ['garden.vert', 'garden.frag'], shadow: ['shadow.vert', 'shadow.frag'],
    });
    // Every program reads a pose texture (at rest until Blow), so one is always bound.
    this.poseTexture = this.gl.createTexture();
    this.poseRows = uploadPoses(this.gl, this.poseTexture, restPoses(1), 1, 0);
    // What the bark units hold for trees without simulated bark (no unit read is left unbound).
    this.blankTexture = imageTexture(this.gl, { width: 1, height: 1, pixels: new Uint8Array([128, 128, 255, 255]) }, this.gl.REPEAT);
  }

  ready() {
    return Boolean(this.programs);
  }

  #drop(part) {
    if (!part) return;
    this.gl.deleteVertexArray(part.vao);
    for (const b of part.buffers) this.gl.deleteBuffer(b);
    if (part.full) this.gl.deleteBuffer(part.full.buffer);
    if (part.lod) this.gl.deleteTexture(part.lod.texture);
  }

  // An indexed mesh (positions, normals, indices, a per-vertex tint or none, a per-vertex birth
  // year or none) in a new VAO; `tintBuffer` is the tint's buffer (the ground's moss light, which
  // another year replaces).
  #mesh(m, tint, birth) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [staticBuffer(gl, m.positions), staticBuffer(gl, m.normals)];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    let tintBuffer = null;
    if (tint) {
      tintBuffer = staticBuffer(gl, tint);
      buffers.push(tintBuffer);
      floatAttribute(gl, 2, tintBuffer, 1);
    }
    if (birth && birth.byteLength > 0) {
      buffers.push(staticBuffer(gl, birth));
      floatAttribute(gl, 4, buffers[buffers.length - 1], 1);
    }
    if (m.uvs && m.uvs.byteLength > 0) {  // the trees' bark uvs (simulated bark)
      buffers.push(staticBuffer(gl, m.uvs));
      floatAttribute(gl, 8, buffers[buffers.length - 1], 2);
    }
    buffers.push(staticBuffer(gl, m.indices, gl.ELEMENT_ARRAY_BUFFER));
    gl.bindVertexArray(null);
    return { vao, buffers, tintBuffer, count: m.indices.byteLength / 4 };
  }

  // buffers: the worker's {ground, objects, trees} (web/bindings/garden_bindings.cpp; used at once:
  // the page may recycle them after this returns); bounds: its boundsJson (size, n, cell, relief,
  // min, max); barks: the worker's per distinct tree simulated bark maps ({bark, barkNormal}:
  // {width, height, pixels, digest}) or null; [] with bark 0.
  setGarden(buffers, bounds, barks = []) {
    const gl = this.gl;
    this.progress.abort();
    this.clear();
    const mossS = buffers.ground.moss_S;
    this.hasMoss = !!mossS && mossS.byteLength > 0;
    this.ground = this.#mesh(buffers.ground, this.hasMoss ? mossS : null);
    this.#groundLod(bounds, buffers.ground);
    this.objects = buffers.objects.indices.byteLength > 0 ? this.#mesh(buffers.objects, buffers.objects.kind, buffers.objects.birth) : null;
    this.year = null;
    this.#setTrees(buffers.trees);
    this.#setBarks(barks);
    this.grid = { n: bounds.n, size: bounds.size, cell: bounds.cell, relief: bounds.relief, heights: copyOf(Float32Array, buffers.ground.heights) };
    this.boundsView = { min: [...bounds.min], max: [...bounds.max] };
    this.serial += 1;
  }

  // The ground's level of detail (ground_lod.js) when it is the grid it says ((n + 1)² vertices, n²
  // cells): its own index buffer in the ground's VAO, rewritten when a frame's tiles change stride.
  #groundLod(bounds, ground) {
    const gl = this.gl, n = bounds.n;
    const heights = viewOf(Float32Array, ground.heights);
    if (!(n > 0) || heights.length !== (n + 1) * (n + 1) || this.ground.count !== n * n * 6 || ground.positions.byteLength !== heights.length * 12) return;
    const lod = new GroundLod(n, bounds.cell, heights);
    lod.full = this.ground.count;
    lod.half = bounds.size / 2;
    // The grid's normal and moss light per vertex as a texture (garden.frag reads them per
    // fragment, so the coarse tiles keep the grid's light).
    const normals = viewOf(Float32Array, ground.normals), moss = this.hasMoss ? viewOf(Float32Array, ground.moss_S) : null;
    lod.map = new Float32Array(heights.length * 4);
    for (let v = 0; v < heights.length; ++v) {
      lod.map.set(normals.subarray(v * 3, v * 3 + 3), v * 4);
      lod.map[v * 4 + 3] = moss ? moss[v] : 0;
    }
    lod.texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, lod.texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, n + 1, n + 1, 0, gl.RGBA, gl.FLOAT, lod.map);
    for (const [k, v] of [[gl.TEXTURE_MIN_FILTER, gl.LINEAR], [gl.TEXTURE_MAG_FILTER, gl.LINEAR], [gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE], [gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE]]) gl.texParameteri(gl.TEXTURE_2D, k, v);
    gl.bindTexture(gl.TEXTURE_2D, null);
    lod.buffer = gl.createBuffer();
    gl.bindVertexArray(this.ground.vao);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, lod.buffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, lod.indices.byteLength, gl.DYNAMIC_DRAW);
    gl.bindVertexArray(null);
    this.ground.buffers.push(lod.buffer);
    this.ground.lod = lod;
    this.ground.count = 0;
  }

  // The ground's indices for `view` (its eye and pixels) uploaded when they changed; the count drawn.
  #groundFor(view) {
    const lod = this.ground.lod;
    if (!lod) return;
    const px = this.lodPx === 0 ? 0 : pixelsAtOneMetre(view.viewProjection, view.height);
    const strides = this.lodPx === 0 ? lod.tiles.map(() => 1) : lod.strides(view.eye, px, this.lodPx);
    const { indices, count, changed } = lod.select(strides);
    if (changed || this.ground.count !== count) {
      const gl = this.gl;
      gl.bindVertexArray(this.ground.vao);
      gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 0, indices);
      gl.bindVertexArray(null);
      this.ground.count = count;
    }
  }

  // Garden year `year` of the garden on screen (the worker's 'gardenYear' buffers: the trees' six
  // buffers and that year's moss_S; used at once, may be recycled after): the trees' meshes
  // replaced, the ground's moss light rewritten in place, the ivy shown to its birth year `year`.
  // `last`: the year is the last grown (its ivy all shown).
  setYear(buffers, year, last) {
    const gl = this.gl;
    this.progress.abort();
    this.#drop(this.trees);
    this.trees = null;
    this.#setTrees(buffers);
    const mossS = buffers.moss_S;
    if (this.hasMoss && this.ground?.tintBuffer && mossS && mossS.byteLength > 0) {
      gl.bindBuffer(gl.ARRAY_BUFFER, this.ground.tintBuffer);
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, viewOf(Float32Array, mossS));
      const lod = this.ground.lod, moss = viewOf(Float32Array, mossS);
      if (lod && moss.length * 4 === lod.map.length) {
        for (let v = 0; v < moss.length; ++v) lod.map[v * 4 + 3] = moss[v];
        gl.bindTexture(gl.TEXTURE_2D, lod.texture);
        gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, lod.n + 1, lod.n + 1, gl.RGBA, gl.FLOAT, lod.map);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
    }
    this.year = last ? null : year;
    this.serial += 1;
  }

  #setTrees(t) {
    const gl = this.gl;
    this.still();
    if (t.indices.byteLength > 0) {
      const trees = this.#mesh(t, t.part);
      trees.vertices = t.positions.byteLength / 12;
      trees.blockBuffer = null;
      trees.blockData = null;
      trees.fullMask = null;
      gl.bindVertexArray(trees.vao);
      trees.instanceBuffer = staticBuffer(gl, t.instances);
      trees.buffers.push(trees.instanceBuffer);
      trees.instanceData = copyOf(Float32Array, t.instances);  // the copies' x, y, z, turn (setFull)
      trees.full = null;  // setFull's buffer of the copies drawn in full, or null (all of them)
      gl.bindVertexArray(null);
      const r = viewOf(Uint32Array, t.ranges);
      trees.groups = [];
      for (let k = 0; k + 3 < r.length; k += 4) {
        trees.groups.push({ firstIndex: r[k], count: r[k + 1], firstInstance: r[k + 2], instances: r[k + 3] });
      }
      this.trees = trees;
    }
  }

  // Each distinct tree's bark textures (the ones before were deleted by clear()); trees sharing
  // one bark run (the same digests) share its textures.
  #setBarks(barks) {
    const gl = this.gl;
    const made = new Map();
    this.barks = (barks || []).map((b) => {
      if (!b || !(b.bark?.width > 0 && b.bark.height > 0 && b.barkNormal?.width > 0 && b.barkNormal.height > 0)) return null;
      const digest = `${b.bark.digest}|${b.barkNormal.digest}`;
      if (!made.has(digest)) made.set(digest, { digest, colour: imageTexture(gl, b.bark, gl.REPEAT), normal: imageTexture(gl, b.barkNormal, gl.REPEAT) });
      return made.get(digest);
    });
  }

  // How many distinct trees wear simulated bark (their textures uploaded).
  barkTrees() {
    return this.barks.filter(Boolean).length;
  }

  // Group k's bark textures on their units, or none (uBarkSim 0), for program `p`.
  #bindBark(p, k) {
    const gl = this.gl;
    if (!p.uniforms.uBarkSim) return;
    const bark = this.barkShown ? this.barks[k] : null;
    gl.uniform1i(p.uniforms.uBarkSim, bark ? 1 : 0);
    gl.activeTexture(gl.TEXTURE0 + BARK_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, bark ? bark.colour : this.blankTexture);
    gl.activeTexture(gl.TEXTURE0 + BARK_UNIT + 1);
    gl.bindTexture(gl.TEXTURE_2D, bark ? bark.normal : this.blankTexture);
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(p.uniforms.uBarkMap, BARK_UNIT);
    gl.uniform1i(p.uniforms.uBarkNormal, BARK_UNIT + 1);
  }

  // The copies drawn in full: mask (Uint8Array, one per copy in the instances' order, 1 = full) or
  // null (every copy). Each group's kept copies are packed into one buffer, with their pose blocks
  // when Blow's skin is on (so the near copies of hybrid mode sway with their own poses).
  setFull(mask) {
    const gl = this.gl, trees = this.trees;
    if (!trees) return;
    this.progress.abort();  // a frame in parts must not draw from the buffer deleted here
    if (trees.full) {
      gl.deleteBuffer(trees.full.buffer);
      if (trees.full.blockBuffer) gl.deleteBuffer(trees.full.blockBuffer);
    }
    trees.full = null;
    trees.fullMask = mask;
    if (!mask) return;
    const data = new Float32Array(trees.instanceData.length);
    const blocks = trees.blockData ? new Float32Array(trees.blockData.length) : null;
    const ranges = [];
    let n = 0;
    for (const g of trees.groups) {
      const first = n;
      for (let k = g.firstInstance; k < g.firstInstance + g.instances; ++k) {
        if (!mask[k]) continue;
        data.set(trees.instanceData.subarray(k * 4, k * 4 + 4), n * 4);
        if (blocks) blocks[n] = trees.blockData[k];
        n += 1;
      }
      ranges.push({ firstInstance: first, instances: n - first });
    }
    trees.full = {
      buffer: staticBuffer(gl, data.subarray(0, Math.max(4, n * 4))), ranges,
      blockBuffer: blocks ? staticBuffer(gl, blocks.subarray(0, Math.max(1, n))) : null,
    };
  }

  // Blow: the worker's 'blowing' skin ({joints: Uint32 and weights: Float32 per vertex of the
  // trees on screen, blocks: Float32 per copy in the instances' order}) on the trees' VAO, used at
  // once (may be recycled after). False when it is not the trees' on screen (a vertex count apart).
  setSkin(skin) {
    const gl = this.gl, trees = this.trees;
    if (!trees || skin.joints.byteLength / 4 !== trees.vertices) return false;
    // A skin given before (an earlier Blow of these trees) is replaced.
    for (const b of trees.skin || []) gl.deleteBuffer(b);
    trees.buffers = trees.buffers.filter((b) => !(trees.skin || []).includes(b));
    gl.bindVertexArray(trees.vao);
    const joints = staticBuffer(gl, skin.joints), weights = staticBuffer(gl, skin.weights);
    uintAttribute(gl, 5, joints, 1);
    floatAttribute(gl, 6, weights, 1);
    gl.bindVertexArray(null);
    trees.blockBuffer = staticBuffer(gl, skin.blocks);
    trees.blockData = copyOf(Float32Array, skin.blocks);
    trees.skin = [joints, weights, trees.blockBuffer];
    trees.buffers.push(...trees.skin);
    if (trees.fullMask) this.setFull(trees.fullMask);  // the near copies' pose blocks too
    return true;
  }

  // Every copy's poses (Float32Array, `blocks` × 16 floats: the worker's 'pose'), the trees then
  // skinned to them.
  setPoses(poses, blocks) {
    if (!this.trees?.blockBuffer) return;
    this.poseRows = uploadPoses(this.gl, this.poseTexture, poses, blocks, this.poseRows);
    this.swayOn = true;
    this.poseSerial += 1;
  }

  // The grown shape again (Still, a regrow, a year picked): the trees drawn unskinned.
  still() {
    this.swayOn = false;
    this.poseSerial = 0;
  }

  clear() {
    this.progress.abort();
    for (const b of new Set(this.barks.filter(Boolean))) {
      this.gl.deleteTexture(b.colour);
      this.gl.deleteTexture(b.normal);
    }
    this.barks = [];
    this.#drop(this.ground);
    this.#drop(this.objects);
    this.#drop(this.trees);
    this.ground = this.objects = this.trees = null;
  }

  // The ground's height under (x, z) (metres): the triangle of its grid under the point, split along
  // the (i, j)-(i + 1, j + 1) diagonal as core/compose/garden_scene.h GardenGround::HeightAt; the
  // point clamped into the square.
  heightAt(x, z) {
    const g = this.grid;
    if (!g) return 0;
    const fx = Math.min(Math.max((x + g.size / 2) / g.cell, 0), g.n);
    const fz = Math.min(Math.max((z + g.size / 2) / g.cell, 0), g.n);
    const i = Math.min(Math.floor(fx), g.n - 1), j = Math.min(Math.floor(fz), g.n - 1);
    const u = fx - i, v = fz - j;
    const h = (a, b) => g.heights[b * (g.n + 1) + a];
    if (u >= v) return h(i, j) + u * (h(i + 1, j) - h(i, j)) + v * (h(i + 1, j + 1) - h(i + 1, j));
    return h(i, j) + v * (h(i, j + 1) - h(i, j)) + u * (h(i + 1, j + 1) - h(i, j + 1));
  }

  // The ray through the canvas point (x, y) (CSS pixels) under `camera`: {origin, direction}.
  rayAt(camera, x, y) {
    return camera.ray(x, y, this.canvas.clientWidth, this.canvas.clientHeight);
  }

  // Where `ray` first meets the ground inside the square: [x, y, z], or null. Marched in steps of
  // a quarter cell, the crossing refined by bisection.
  groundHit(ray) {
    const g = this.grid;
    if (!g) return null;
    const { origin: o, direction: d } = ray;
    const above = (s) => o[1] + d[1] * s - this.heightAt(o[0] + d[0] * s, o[2] + d[2] * s);
    const half = g.size / 2;
    const step = g.cell / 4;
    const far = Math.hypot(o[0], o[1], o[2]) + 2 * g.size + g.relief;
    let prev = 0;
    if (above(0) < 0) return null;
    for (let s = step; s <= far; s += step) {
      if (above(s) > 0) {
        prev = s;
        continue;
      }
      let lo = prev, hi = s;
      for (let k = 0; k < 40; ++k) {
        const mid = (lo + hi) / 2;
        if (above(mid) > 0) lo = mid;
        else hi = mid;
      }
      const p = [o[0] + d[0] * hi, 0, o[2] + d[2] * hi];
      if (Math.abs(p[0]) > half || Math.abs(p[2]) > half) return null;
      p[1] = this.heightAt(p[0], p[2]);
      return p;
    }
    return null;
  }

  // The trees' draw of triangles [first, first + count) of group `g` over its instances (each
  // instance `tris` triangles): partial instances drawn alone, whole ones in one instanced draw.
  // copies: {firstInstance, instances} of the instance buffer, or of setFull's when `full`.
  #drawGroup(g, first, count, copies, full) {
    const gl = this.gl;
    const tris = g.count / 3;
    // once skinned, always pointed at its copies (in range); the copies of setFull with their own
    // blocks, packed as they are
    const blocks = full ? full.blockBuffer : this.trees.blockBuffer;
    const buffer = full ? full.buffer : this.trees.instanceBuffer;
    const draw = (instance, from, n, instances) => {
      floatAttribute(gl, 3, buffer, 4, INSTANCE_BYTES, (copies.firstInstance + instance) * INSTANCE_BYTES, 1);
      if (blocks) floatAttribute(gl, 7, blocks, 1, 4, ((full ? copies.firstInstance : g.firstInstance) + instance) * 4, 1);
      gl.drawElementsInstanced(gl.TRIANGLES, n * 3, gl.UNSIGNED_INT, (g.firstIndex + from * 3) * 4, instances);
    };
    let at = first;
    const end = first + count;
    while (at < end) {
      const instance = Math.floor(at / tris), from = at - instance * tris;
      if (from === 0 && end - at >= tris) {
        const whole = Math.floor((end - at) / tris);
        draw(instance, 0, tris, whole);
        at += whole * tris;
      } else {
        const n = Math.min(tris - from, end - at);
        draw(instance, from, n, 1);
        at += n;
      }
    }
  }

  // The pose texture on its unit for program `p`, skinning on (`sway`) or off; the generic values
  // of the skin's attributes where a VAO has no array for them (an integer attribute's must be
  // integer).
  #bindSway(p, sway) {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + POSE_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, this.poseTexture);
    gl.activeTexture(gl.TEXTURE0);
    if (p.uniforms.uPoses) gl.uniform1i(p.uniforms.uPoses, POSE_UNIT);
    if (p.uniforms.uSway) gl.uniform1i(p.uniforms.uSway, sway ? 1 : 0);
    gl.vertexAttribI4ui(5, 0, 0, 0, 0);
    gl.vertexAttrib1f(6, 0);
    gl.vertexAttrib1f(7, 0);
    gl.vertexAttrib2f(8, 0, 0);  // no bark uvs (a VAO without them)
  }

  // A step of an indexed mesh (the ground, the objects) with the program `p` set up by `uniforms`.
  #meshStep(part, uniforms, p) {
    const gl = this.gl;
    return {
      primitives: part.count / 3,
      setup: () => {
        gl.bindVertexArray(part.vao);
        uniforms();
        this.#bindSway(p, false);
        this.#bindBark(p, -1);
        gl.vertexAttrib4f(3, 0, 0, 0, 0);  // not an array in these VAOs: the generic value (no turn)
        gl.vertexAttrib1f(4, 0);  // born in year 0 (the objects' VAO has its ivy's birth years)
      },
      draw: (first, n) => gl.drawElements(gl.TRIANGLES, n * 3, gl.UNSIGNED_INT, first * 12),
    };
  }

  // every: all copies (the shadow map: kept while the camera moves, so the far copies drawn as
  // cards still cast their full shadow), else the copies of setFull.
  #treeSteps(uniforms, p, every = false) {
    const gl = this.gl;
    if (!this.trees) return [];
    const full = every ? null : this.trees.full;
    return this.trees.groups.map((g, k) => ({ g, k, copies: full ? full.ranges[k] : g }))
      .filter(({ g, copies }) => g.count > 0 && copies.instances > 0).map(({ g, k, copies }) => ({
        primitives: (g.count / 3) * copies.instances,
        setup: () => {
          gl.bindVertexArray(this.trees.vao);
          uniforms();
          this.#bindSway(p, this.swayOn && !!(full ? full.blockBuffer : this.trees.blockBuffer));
          this.#bindBark(p, k);
          gl.vertexAttrib1f(4, 0);
        },
        draw: (first, n) => this.#drawGroup(g, first, n, copies, full),
      }));
  }

  // The year the ivy is shown to (every ivy vertex at the last year grown).
  #shownYear() {
    return this.year === null ? 1e9 : this.year;
  }

  shadowKey() {
    // The poses after '#': a swaying frame (the page's motion) reuses the map of an older pose.
    return this.objects || this.trees ? `garden:${this.serial}#${this.swayOn ? this.poseSerial : 'rest'}` : null;
  }

  worldBounds() {
    return this.boundsView;
  }

  shadowSteps(sun) {
    const gl = this.gl;
    const s = this.programs.shadow;
    const uniforms = () => {
      gl.useProgram(s.program);
      gl.uniformMatrix4fv(s.uniforms.uSunViewProjection, false, sun.matrix);
      gl.uniform1f(s.uniforms.uYear, this.#shownYear());
      gl.disable(gl.CULL_FACE);
    };
    const steps = [];
    if (this.objects) steps.push(this.#meshStep(this.objects, uniforms, s));
    steps.push(...this.#treeSteps(uniforms, s, true));
    return steps;
  }

  layerSteps(view) {
    const gl = this.gl;
    const p = this.programs.mesh;
    const totals = { triangles: 0, drawCalls: 0, primitives: 0, trees: 0 };
    if (!this.ground) return { steps: [], totals };
    const uniforms = (mode) => () => {
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, view.viewProjection);
      gl.uniform3fv(p.uniforms.uLightDirection, view.light);
      gl.uniform1i(p.uniforms.uMode, mode);
      gl.uniform1f(p.uniforms.uRelief, this.grid ? this.grid.relief : 1);
      // The ground's overlay (garden.frag): none, the moss's light (needs moss_S), slope, altitude
      // bands (a band a metre, or relief/10 when that is more than 10 bands).
      const overlay = OVERLAYS.indexOf(this.overlay);
      gl.uniform1i(p.uniforms.uOverlay, overlay === 1 && !this.hasMoss ? 0 : Math.max(0, overlay));
      gl.uniform1f(p.uniforms.uBand, Math.max(1, (this.grid ? this.grid.relief : 1) / 10));
      gl.uniform1f(p.uniforms.uYear, this.#shownYear());
      // The ground's per-vertex map when its level of detail draws it (a blank texture otherwise:
      // the sampler is never left on another unit).
      const lod = mode === 0 && this.lodPx !== 0 ? this.ground.lod : null;
      gl.activeTexture(gl.TEXTURE0 + GROUND_UNIT);
      gl.bindTexture(gl.TEXTURE_2D, lod ? lod.texture : this.blankTexture);
      gl.activeTexture(gl.TEXTURE0);
      gl.uniform1i(p.uniforms.uGroundMap, GROUND_UNIT);
      gl.uniform4f(p.uniforms.uGround, lod ? lod.half : 0, lod ? lod.cell : 1, lod ? lod.n + 1 : 1, lod ? 1 : 0);
      view.shadow?.bindFor(p, view.sun);
      gl.enable(gl.DEPTH_TEST);
      gl.disable(gl.CULL_FACE);
      gl.vertexAttrib1f(2, 0);  // the ground's tint (not an array in its VAO)
    };
    this.#groundFor(view);
    const steps = [this.#meshStep(this.ground, uniforms(0), p)];
    if (this.objects) steps.push(this.#meshStep(this.objects, uniforms(1), p));
    const trees = this.#treeSteps(uniforms(2), p);
    steps.push(...trees);
    for (const s of steps) totals.triangles += s.primitives;
    totals.drawCalls = steps.length;
    totals.groundTriangles = this.ground.count / 3;
    totals.groundStrides = this.ground.lod ? this.ground.lod.key : '';
    totals.trees = this.trees ? this.trees.groups.reduce((n, g) => n + g.instances, 0) : 0;
    totals.fullTrees = this.trees?.full ? this.trees.full.ranges.reduce((n, r) => n + r.instances, 0) : totals.trees;
    return { steps, totals };
  }

  dispose() {
    super.dispose();
    this.clear();
    for (const p of Object.values(this.programs || {})) this.gl.deleteProgram(p.program);
    if (this.poseTexture) this.gl.deleteTexture(this.poseTexture);
    if (this.blankTexture) this.gl.deleteTexture(this.blankTexture);
    this.programs = null;
  }
}
