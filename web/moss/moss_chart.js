// The moss page's population per day (the stats' population.by_day, as `niwa moss grow --stats`
// writes it): a small SVG chart with one line per species and a marker on the day the scrubber
// shows, and the same days as CSV text for a download (day, one column per species, total).
// The marker is an HTML element over the SVG moved by a CSS transform (its own compositor layer,
// public/style.css), so a scrubbed day repaints none of the chart's lines.
// Does not: grow, replay mosses (moss_renderer.js does) or read anything but the stats object.

const SVG = 'http://www.w3.org/2000/svg';
// The tufts' species colours (shaders/moss/tuft.vert), a little darker so a line reads on white.
export const SPECIES_COLOURS = ['#7f9466', '#7a9414', '#1f6624'];
const W = 300, H = 120, PAD = { left: 34, right: 8, top: 8, bottom: 20 };

// The per-day CSV of a run's stats: a header `day,<species...>,total` and one row per day 0..N.
export function populationCsv(stats) {
  const species = stats?.population?.species || [];
  const byDay = stats?.population?.by_day || [];
  const lines = [['day', ...species, 'total'].join(',')];
  byDay.forEach((counts, day) => lines.push([day, ...counts, counts.reduce((a, b) => a + b, 0)].join(',')));
  return `${lines.join('\n')}\n`;
}

function node(name, attrs, parent) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.append(e);
  return e;
}

export class PopulationChart {
  // svg: an <svg> element (its content is replaced); legend: an element for the species' names;
  // marker: an element absolutely placed over the SVG, as wide as it (its left edge is the line).
  constructor(svg, legend, marker = null) {
    this.svg = svg;
    this.legend = legend;
    this.markerElement = marker;
    this.marker = null;
    svg.setAttribute('viewBox', `0 0 ${W} ${H}`);
    this.days = 0;
    this.max = 1;
  }

  x(day) {
    return PAD.left + (this.days > 0 ? (day / this.days) * (W - PAD.left - PAD.right) : 0);
  }

  y(count) {
    return H - PAD.bottom - (count / this.max) * (H - PAD.top - PAD.bottom);
  }

  // Draws the lines of stats.population (species names, by_day counts).
  set(stats) {
    const species = stats?.population?.species || [];
    const byDay = stats?.population?.by_day || [];
    this.svg.replaceChildren();
    this.days = Math.max(byDay.length - 1, 0);
    this.max = Math.max(1, ...byDay.flat());
    node('line', { x1: PAD.left, y1: this.y(0), x2: W - PAD.right, y2: this.y(0), class: 'axis' }, this.svg);
    node('line', { x1: PAD.left, y1: PAD.top, x2: PAD.left, y2: this.y(0), class: 'axis' }, this.svg);
    const label = (x, y, text, anchor) => {
      node('text', { x, y, 'text-anchor': anchor, class: 'tick' }, this.svg).textContent = text;
    };
    label(PAD.left - 3, PAD.top + 8, String(this.max), 'end');
    label(PAD.left - 3, this.y(0), '0', 'end');
    label(PAD.left, H - 5, 'day 0', 'start');
    label(W - PAD.right, H - 5, `day ${this.days}`, 'end');
    this.lines = species.map((name, s) => {
      const points = byDay.map((counts, day) => `${this.x(day).toFixed(1)},${this.y(counts[s]).toFixed(1)}`).join(' ');
      return node('polyline', { points, fill: 'none', stroke: SPECIES_COLOURS[s] || '#333', 'stroke-width': 1.5, 'data-species': name }, this.svg);
    });
    this.marker = this.markerElement;
    if (this.marker) {
      this.marker.style.top = `${(100 * PAD.top) / H}%`;
      this.marker.style.height = `${(100 * (this.y(0) - PAD.top)) / H}%`;
      this.mark(this.days);
    }
    if (this.legend) {
      this.legend.replaceChildren(...species.map((name, s) => {
        const span = document.createElement('span');
        span.style.color = SPECIES_COLOURS[s] || '#333';
        span.textContent = `■ ${name}`;
        return span;
      }));
    }
  }

  // Moves the marker to `day` (clamped to the run's days); returns the day marked.
  mark(day) {
    const d = Math.max(0, Math.min(this.days, Number.isFinite(day) ? day : this.days));
    if (this.marker) {
      const x = this.x(d);
      this.marker.style.transform = `translateX(calc(${((100 * x) / W).toFixed(3)}% - 0.6px))`;
      this.marker.dataset.x = x.toFixed(1);  // in the SVG's viewBox units (tests)
      this.marker.dataset.day = String(d);
    }
    return d;
  }
}
