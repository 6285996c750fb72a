// The tree page's draw-primitive table (like thesis table 4.1: this view vs full polygons) and the
// stats line's frame cost: triangles and draw calls of the last frame (from the index counts drawn)
// and the CPU time of the render call averaged over the last 30 frames drawn.
// Does not: count anything itself (the renderer and the worker's table 4.1 counts do).
import { FrameTimes } from '../shell/study_page.js';
import { bumpHook, setHooks } from '../shell/test_hooks.js';

// A count with thousands commas, as toLocaleString('en-US') writes it ("1,234,567"), without ICU:
// the page's first toLocaleString builds its number formatter, 12 ms of main-thread CPU (67 ms of
// wall time at load 8) in the first frame's message during the tree page's load (issue 32 item 5).
export const withCommas = (n) => (Number.isSafeInteger(n) ? String(n).replace(/\B(?=(\d{3})+$)/g, ',') : n.toLocaleString('en-US'));

// What a frame draws, as the stats line says it: "tris N · draw calls M".
const frameSize = (drawn) => `tris ${withCommas(Math.round(drawn.triangles))} · draw calls ${drawn.drawCalls}`;

export class RenderTable {
  // table: the <table> with data-row / data-full cells; column: the header cell of the view
  // column; frameLine: the element of the frame-cost line.
  constructor(table, column, frameLine) {
    this.table = table;
    this.column = column;
    this.frameLine = frameLine;
    this.times = new FrameTimes();
  }

  // One cell: column 'row' (this view) or 'full'; key as in the table's data-* attributes.
  set(column, key, value) {
    const cell = this.table.querySelector(`[data-${column}="${key}"]`);
    if (cell) cell.textContent = typeof value === 'number' ? withCommas(value) : String(value);
  }

  // A frame drawn ({triangles, drawCalls, cpuMs, mode}, as Renderer.render returns it).
  showFrame(drawn) {
    const avg = this.times.push(drawn.cpuMs);
    this.frameLine.textContent = `${frameSize(drawn)} · frame ${avg.toFixed(1)} ms CPU`;
    this.frameLine.title = `CPU time of the render call, mean of the last ${this.times.count} frames drawn (GPU time is not measured)`;
    const column = drawn.mode === 'hybrid' ? 'row' : 'full';
    this.set(column, 'draw_calls', drawn.drawCalls);
    this.set(column, 'frame_ms', `${avg.toFixed(1)} ms`);
    if (drawn.mode !== 'hybrid') for (const key of ['draw_calls', 'frame_ms']) this.set('row', key, '');
  }

  // A frame drawn in parts, not finished yet: its size and that it is on its way (the line would
  // otherwise show the last finished frame's, e.g. the ground alone before a big tree's first frame).
  showPartial(drawn) {
    this.frameLine.textContent = `${frameSize(drawn)} · drawing in parts…`;
    this.frameLine.title = 'This frame is too big for one animation frame: it is drawn over several and shown when finished';
  }

  // The full-polygon column from the worker's mesh (ArrayBuffers; 12 bytes per triangle).
  showFullCounts(mesh) {
    const tris = (part) => (part ? part.indices.byteLength / 12 : 0);
    const bark = tris(mesh.bark), leaves = tris(mesh.leaves) + tris(mesh.flowers);
    this.set('full', 'branch_polygons', bark);
    this.set('full', 'leaf_polygons', leaves);
    this.set('full', 'total_polygons', bark + leaves);
  }

  // The view column from a drawList's table 4.1 stats, or cleared (null).
  showHybridCounts(stats) {
    this.column.textContent = stats ? 'hybrid' : 'this view';
    for (const key of ['lines', 'branch_polygons', 'leaf_polygons', 'total_polygons', 'textures']) {
      this.set('row', key, stats ? stats[key] : '');
    }
    if (!stats) return;
    setHooks({
      renderLines: stats.lines,
      renderPolygons: stats.total_polygons,
      renderTextures: stats.textures,
      renderFull: stats.full_polygons,
      // Every alive branch is a line or a card in every view (none vanishes while switching).
      renderUnassigned: stats.alive_branches - stats.line_branches - stats.card_branches,
    });
    bumpHook('renderViews');
  }
}
