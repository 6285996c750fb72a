// The terrain page's 2-D plan view (a canvas 2D): every contour of the last mountain from above,
// coloured by height (the hypsometric ramp), summits as red dots, north up; and the seed contour
// drawn with mouse, pen or finger: one press-drag-release is one closed polyline (the closing edge
// is implied), handed over in metres (x east, y north) in the frame of the mountain shown.
// Does not: check the drawing's geometry (the core's CheckSeed does; a crossing drawing comes back
// as its one line), talk to the worker, or keep history.
import { viewOf } from '../gl/buffers.js';

const MARGIN = 0.08;      // of the shown box, around the mountain
const MIN_STEP_PX = 3;    // a pointer move shorter than this adds no point
export const MAX_DRAWN_POINTS = 600;
const STROKE_COLOUR = '#1f5fa8';  // the stroke being drawn

// The hypsometric ramp of core/terrain/terrain_output.cpp HypsometricColour (its four stops:
// green, ochre, brown, white), so the plan's colours are the 3-D view's and the .glb's.
export function ramp(t) {
  const stops = [[0, [0.33, 0.52, 0.27]], [1 / 3, [0.72, 0.66, 0.38]], [2 / 3, [0.52, 0.38, 0.26]], [1, [0.96, 0.96, 0.96]]];
  for (let k = 1; k < stops.length; ++k) {
    if (t <= stops[k][0]) {
      const [t0, a] = stops[k - 1], [t1, b] = stops[k];
      const u = (t - t0) / (t1 - t0 || 1);
      return a.map((x, i) => Math.round(255 * (x + (b[i] - x) * u)));
    }
  }
  return stops[stops.length - 1][1].map((x) => Math.round(255 * x));
}

export class PlanView {
  // onDrawn(points: [[x, y], ...] in metres, pixels: {width, height} of the drawing's box).
  constructor(canvas, onDrawn) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.onDrawn = onDrawn;
    this.lines = null;    // {positions: Float32Array (x, h, −y) pairs, height: Float32Array}
    this.summits = null;  // Float32Array (x, h, −y)
    this.box = { min: [-1, -1], max: [1, 1] };
    this.range = [0, 1];
    this.stroke = null;   // pixel points while drawing
    this.level = Infinity;  // contours above it are not drawn (the level scrubber)
    this.cache = null;      // {key, canvas}: the mountain's picture (#picture)
    canvas.addEventListener('pointerdown', (e) => this.#down(e));
    canvas.addEventListener('pointermove', (e) => this.#move(e));
    canvas.addEventListener('pointerup', (e) => this.#up(e));
    canvas.addEventListener('pointercancel', () => { this.stroke = null; this.draw(); });
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  // The last mountain's contours and summits (the worker's buffers, ArrayBuffers or views: read
  // in place, not copied; the page hands them back to the worker once a newer mountain is set)
  // and its box in metres.
  setTerrain(buffers, bounds) {
    this.lines = {
      positions: viewOf(Float32Array, buffers.contours.positions), height: viewOf(Float32Array, buffers.contours.height),
      level: viewOf(Float32Array, buffers.contours.level),
    };
    this.summits = viewOf(Float32Array, buffers.summits.positions);
    this.box = { min: bounds.min, max: bounds.max };
    this.range = [bounds.h_min, bounds.h_max];
    this.cache = null;
    this.draw();
  }

  setLevel(k) {
    this.level = k;
    this.cache = null;
    this.draw();
  }

  // Metres per pixel and the box's origin, square, centred, with a margin.
  #frame() {
    const w = this.canvas.width, h = this.canvas.height;
    const sx = this.box.max[0] - this.box.min[0], sy = this.box.max[1] - this.box.min[1];
    const size = Math.max(sx, sy, 1e-9) * (1 + 2 * MARGIN);
    const perPx = size / Math.min(w, h);
    const cx = (this.box.min[0] + this.box.max[0]) / 2, cy = (this.box.min[1] + this.box.max[1]) / 2;
    return { perPx, cx, cy, w, h };
  }

  toPixel(x, y) {
    const f = this.#frame();
    return [f.w / 2 + (x - f.cx) / f.perPx, f.h / 2 - (y - f.cy) / f.perPx];
  }

  toMetres(px, py) {
    const f = this.#frame();
    return [f.cx + (px - f.w / 2) * f.perPx, f.cy - (py - f.h / 2) * f.perPx];
  }

  #pixelOf(e) {
    const r = this.canvas.getBoundingClientRect();
    return [(e.clientX - r.left) * (this.canvas.width / r.width), (e.clientY - r.top) * (this.canvas.height / r.height)];
  }

  #down(e) {
    if (e.button !== 0) return;
    this.canvas.setPointerCapture(e.pointerId);
    this.stroke = [this.#pixelOf(e)];
    this.draw();
  }

  #move(e) {
    if (!this.stroke) return;
    const p = this.#pixelOf(e);
    const q = this.stroke[this.stroke.length - 1];
    if (Math.hypot(p[0] - q[0], p[1] - q[1]) < MIN_STEP_PX) return;
    this.stroke.push(p);
    // The new piece only, over what is on the canvas (the whole picture is drawn again on
    // release): the work of a pointer move stays the same however large the mountain is.
    const g = this.ctx;
    g.save();
    g.strokeStyle = STROKE_COLOUR;
    g.lineWidth = 2 * Math.min(window.devicePixelRatio || 1, 2);
    g.lineCap = 'round';
    g.beginPath();
    g.moveTo(q[0], q[1]);
    g.lineTo(p[0], p[1]);
    g.stroke();
    g.restore();
  }

  #up(e) {
    if (!this.stroke) return;
    const stroke = this.stroke;
    this.stroke = null;
    const p = this.#pixelOf(e);
    const q = stroke[stroke.length - 1];
    if (Math.hypot(p[0] - q[0], p[1] - q[1]) >= MIN_STEP_PX) stroke.push(p);
    // At most MAX_DRAWN_POINTS points (every k-th), each rounded to a centimetre (a short hash).
    const k = Math.ceil(stroke.length / MAX_DRAWN_POINTS);
    const kept = stroke.filter((_, i) => i % k === 0);
    const xs = kept.map((s) => s[0]), ys = kept.map((s) => s[1]);
    const pixels = { width: Math.max(...xs) - Math.min(...xs), height: Math.max(...ys) - Math.min(...ys), points: kept.length };
    const points = kept.map(([px, py]) => this.toMetres(px, py).map((v) => Number(v.toFixed(2))));
    this.draw();
    this.onDrawn(points, pixels);
  }

  // A scale bar (1, 2 or 5 × 10^k m, about a quarter of the width) and N, bottom left.
  #scaleBar(g, dpr) {
    const f = this.#frame();
    const want = (f.w / 4) * f.perPx;
    const p = 10 ** Math.floor(Math.log10(want));
    const metres = [5, 2, 1].map((m) => m * p).find((m) => m <= want) || p;
    const px = metres / f.perPx, x = 10 * dpr, y = f.h - 10 * dpr;
    g.strokeStyle = '#333';
    g.fillStyle = '#333';
    g.lineWidth = 2 * dpr;
    g.beginPath();
    g.moveTo(x, y);
    g.lineTo(x + px, y);
    g.stroke();
    g.font = `${11 * dpr}px sans-serif`;
    g.fillText(`${metres >= 1000 ? `${metres / 1000} km` : `${metres} m`}`, x, y - 5 * dpr);
    g.fillText('N ↑', f.w - 30 * dpr, 16 * dpr);
  }

  // The mountain's picture (background, contours, summits, scale bar) on an offscreen canvas of
  // the plan's size, drawn again only when the mountain, the level or the size changes: a stroke
  // being drawn redraws on every pointer move, and stroking every contour segment on its own
  // then (3,991 segments on jacksboro, improved: one raster pass each in the GPU process) made a
  // 90-point drawing take 13-49 s in headless Chromium while the page's script sat idle.
  // Consecutive segments of one colour go in one path (one stroke a contour, not one a segment).
  #picture(w, h, dpr) {
    const key = `${w}x${h}@${dpr}`;
    if (this.cache && this.cache.key === key) return this.cache.canvas;
    const canvas = this.cache?.canvas || document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    const g = canvas.getContext('2d');
    g.fillStyle = '#f4f1ea';
    g.fillRect(0, 0, w, h);
    if (this.lines) {
      const pos = this.lines.positions, hh = this.lines.height, level = this.lines.level;
      const span = this.range[1] - this.range[0] || 1;
      g.lineWidth = dpr;
      let style = null, end = null;
      for (let v = 0; v + 1 < pos.length / 3; v += 2) {
        if (level[v] > this.level + 0.5) continue;
        const [r, gg, b] = ramp((hh[v] - this.range[0]) / span);
        const next = `rgb(${Math.round(r * 0.75)},${Math.round(gg * 0.75)},${Math.round(b * 0.75)})`;
        const a = this.toPixel(pos[3 * v], -pos[3 * v + 2]), bb = this.toPixel(pos[3 * v + 3], -pos[3 * v + 5]);
        if (next !== style) {
          if (style !== null) g.stroke();
          g.strokeStyle = style = next;
          g.beginPath();
          end = null;
        }
        if (!end || end[0] !== a[0] || end[1] !== a[1]) g.moveTo(a[0], a[1]);
        g.lineTo(bb[0], bb[1]);
        end = bb;
      }
      if (style !== null) g.stroke();
    }
    if (this.summits && !Number.isFinite(this.level)) {
      g.fillStyle = '#c0392b';
      g.beginPath();
      for (let s = 0; s < this.summits.length / 3; ++s) {
        const p = this.toPixel(this.summits[3 * s], -this.summits[3 * s + 2]);
        g.moveTo(p[0] + 3 * dpr, p[1]);
        g.arc(p[0], p[1], 3 * dpr, 0, 2 * Math.PI);
      }
      g.fill();
    }
    this.#scaleBar(g, dpr);
    this.cache = { key, canvas };
    return canvas;
  }

  draw() {
    const c = this.canvas, g = this.ctx;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const w = Math.max(1, Math.round(c.clientWidth * dpr)), h = Math.max(1, Math.round(c.clientHeight * dpr));
    if (c.width !== w || c.height !== h) {
      c.width = w;
      c.height = h;
    }
    g.drawImage(this.#picture(w, h, dpr), 0, 0);
    if (this.stroke && this.stroke.length > 1) {
      g.strokeStyle = STROKE_COLOUR;
      g.lineWidth = 2 * dpr;
      g.beginPath();
      g.moveTo(this.stroke[0][0], this.stroke[0][1]);
      for (const p of this.stroke.slice(1)) g.lineTo(p[0], p[1]);
      g.stroke();
    }
  }
}
