// The garden ground's level of detail for drawing (issue 33 item 7: a 512² terrain is 524 k triangles,
// most of them under a pixel in the whole-garden view, and SwiftShader pays per triangle): the
// ground's grid (GardenGround::Mesh's vertex order, (n + 1)² vertices, vertex (i, j) at j (n + 1) + i)
// cut into tiles of TILE cells a side, each drawn with every s-th vertex (s a power of two) such that
// one of its cells spans at most LOD_PX pixels at the tile's nearest point to the eye. A tile's edge
// next to a coarser tile takes the neighbour's stride (its edge vertices between the neighbour's
// collapsed onto the one before along the edge, the triangles so emptied left out), so the ground
// stays closed: no crack, no T-junction. The vertices drawn are the grid's own (heights, normals
// and moss light sampled exactly there), only fewer of them far away; near the eye (a close-up) the
// ground is the full grid.
// Does not: touch WebGL (garden_renderer.js uploads the indices), or change the ground's heights
// for clicks (garden_renderer.js heightAt reads the full grid).

export const TILE = 64;      // cells a tile side (the last tile of a row may be shorter)
export const LOD_PX = 12;    // the most pixels a drawn cell may span at its tile's nearest point

export class GroundLod {
  // n: cells a side; cell: metres a cell; heights: Float32Array of (n + 1)² heights (metres).
  constructor(n, cell, heights) {
    this.n = n;
    this.cell = cell;
    this.m = n + 1;
    this.half = (n * cell) / 2;
    this.tiles = [];
    this.across = Math.ceil(n / TILE);
    for (let tj = 0; tj < this.across; ++tj) {
      for (let ti = 0; ti < this.across; ++ti) {
        const i0 = ti * TILE, j0 = tj * TILE, w = Math.min(TILE, n - i0), h = Math.min(TILE, n - j0);
        let lo = Infinity, hi = -Infinity;
        for (let j = j0; j <= j0 + h; ++j) {
          for (let i = i0; i <= i0 + w; ++i) {
            const y = heights[j * this.m + i];
            lo = Math.min(lo, y);
            hi = Math.max(hi, y);
          }
        }
        // the largest power of two dividing both sides (the tile's coarsest stride)
        let most = 1;
        while (w % (most * 2) === 0 && h % (most * 2) === 0 && most * 2 <= Math.min(w, h)) most *= 2;
        this.tiles.push({ i0, j0, w, h, lo, hi, most });
      }
    }
    this.indices = new Uint32Array(n * n * 6);
    this.key = '';
    this.count = 0;
  }

  // Each tile's stride for an eye at `eye` (metres) where one metre at distance d spans
  // pixelsAt1m / d pixels, a drawn cell at most `most` pixels: [s per tile].
  strides(eye, pixelsAt1m, most = LOD_PX) {
    return this.tiles.map((t) => {
      const x0 = -this.half + t.i0 * this.cell, x1 = x0 + t.w * this.cell;
      const z0 = -this.half + t.j0 * this.cell, z1 = z0 + t.h * this.cell;
      const dx = Math.max(x0 - eye[0], 0, eye[0] - x1), dz = Math.max(z0 - eye[2], 0, eye[2] - z1);
      const dy = Math.max(t.lo - eye[1], 0, eye[1] - t.hi);
      const d = Math.max(Math.hypot(dx, dy, dz), 1e-6);
      const px = (this.cell * pixelsAt1m) / d;  // one cell's pixels there
      let s = 1;
      while (s * 2 <= t.most && s * 2 * px <= most) s *= 2;
      return s;
    });
  }

  // The indices for `strides` (one per tile), rebuilt only when they changed: {indices (a view of
  // the first count entries), count, changed}.
  select(strides) {
    const key = strides.join(',');
    if (key === this.key) return { indices: this.indices.subarray(0, this.count), count: this.count, changed: false };
    this.key = key;
    const A = this.across, m = this.m, out = this.indices;
    let o = 0;
    this.tiles.forEach((t, k) => {
      const s = strides[k];
      const ti = k % A, tj = Math.floor(k / A);
      // each edge's stride: the coarser of this tile's and its neighbour's (none at the border)
      const edge = (di, dj) => {
        const a = ti + di, b = tj + dj;
        return a < 0 || b < 0 || a >= A || b >= A ? s : Math.max(s, strides[b * A + a]);
      };
      const left = edge(-1, 0), right = edge(1, 0), low = edge(0, -1), high = edge(0, 1);
      // A vertex (li, lj) of the tile (local cells) moved along its edge onto the edge's stride.
      const at = (li, lj) => {
        if (li === 0 && lj !== 0 && lj !== t.h) lj = Math.floor(lj / left) * left;
        else if (li === t.w && lj !== 0 && lj !== t.h) lj = Math.floor(lj / right) * right;
        else if (lj === 0 && li !== 0 && li !== t.w) li = Math.floor(li / low) * low;
        else if (lj === t.h && li !== 0 && li !== t.w) li = Math.floor(li / high) * high;
        return (t.j0 + lj) * m + t.i0 + li;
      };
      for (let lj = 0; lj < t.h; lj += s) {
        for (let li = 0; li < t.w; li += s) {
          // GardenGround::Mesh's split: (v00, v11, v10) and (v00, v01, v11)
          const v00 = at(li, lj), v10 = at(li + s, lj), v01 = at(li, lj + s), v11 = at(li + s, lj + s);
          if (v00 !== v11 && v11 !== v10 && v10 !== v00) {
            out[o++] = v00; out[o++] = v11; out[o++] = v10;
          }
          if (v00 !== v01 && v01 !== v11 && v11 !== v00) {
            out[o++] = v00; out[o++] = v01; out[o++] = v11;
          }
        }
      }
    });
    this.count = o;
    return { indices: out.subarray(0, o), count: o, changed: true };
  }
}

// One metre's pixels at a distance of one metre under `viewProjection` (a perspective times a
// look-at, column-major) on a drawing buffer `height` pixels high: f H / 2, f = 1 / tan(fovY / 2)
// the length of the matrix's y row (the view's rotation keeps it).
export function pixelsAtOneMetre(viewProjection, height) {
  const m = viewProjection;
  return (Math.hypot(m[1], m[5], m[9]) * height) / 2;
}
