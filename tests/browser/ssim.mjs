// Structural similarity (SSIM, Wang et al. 2004) of two grey images, as the browser tests compute it.
// Grey = Rec. 601 luma in [0, 255]; local statistics over an 11 x 11 Gaussian window (sigma 1.5),
// C1 = (0.01 L)^2, C2 = (0.03 L)^2 with L = 255; the result is the mean SSIM over the windows that
// lie inside the image (or inside the rectangle `box` = {x0, y0, x1, y1}, x1/y1 exclusive).

const RADIUS = 5;
const KERNEL = (() => {
  const k = [];
  let sum = 0;
  for (let i = -RADIUS; i <= RADIUS; ++i) {
    const w = Math.exp(-(i * i) / (2 * 1.5 * 1.5));
    k.push(w);
    sum += w;
  }
  return k.map((w) => w / sum);
})();

// Separable Gaussian blur of a Float64Array image (width x height), valid region only: the result
// at (x, y) is the window centred there; borders within RADIUS are left 0 and never read.
function blur(src, width, height) {
  const tmp = new Float64Array(src.length);
  const out = new Float64Array(src.length);
  for (let y = 0; y < height; ++y) {
    for (let x = RADIUS; x < width - RADIUS; ++x) {
      let s = 0;
      for (let i = -RADIUS; i <= RADIUS; ++i) s += KERNEL[i + RADIUS] * src[y * width + x + i];
      tmp[y * width + x] = s;
    }
  }
  for (let y = RADIUS; y < height - RADIUS; ++y) {
    for (let x = RADIUS; x < width - RADIUS; ++x) {
      let s = 0;
      for (let i = -RADIUS; i <= RADIUS; ++i) s += KERNEL[i + RADIUS] * tmp[(y + i) * width + x];
      out[y * width + x] = s;
    }
  }
  return out;
}

// a, b: grey values (any array-like of width * height numbers).
export function ssim(a, b, width, height, box = null) {
  if (a.length !== width * height || b.length !== width * height) throw new Error('ssim: size mismatch');
  const n = width * height;
  const x = Float64Array.from(a), y = Float64Array.from(b);
  const xx = new Float64Array(n), yy = new Float64Array(n), xy = new Float64Array(n);
  for (let i = 0; i < n; ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const [mx, my, sxx, syy, sxy] = [x, y, xx, yy, xy].map((img) => blur(img, width, height));
  const c1 = (0.01 * 255) ** 2, c2 = (0.03 * 255) ** 2;
  const x0 = Math.max(RADIUS, box ? box.x0 : 0), x1 = Math.min(width - RADIUS, box ? box.x1 : width);
  const y0 = Math.max(RADIUS, box ? box.y0 : 0), y1 = Math.min(height - RADIUS, box ? box.y1 : height);
  let sum = 0, count = 0;
  for (let py = y0; py < y1; ++py) {
    for (let px = x0; px < x1; ++px) {
      const i = py * width + px;
      const vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i], cov = sxy[i] - mx[i] * my[i];
      sum += ((2 * mx[i] * my[i] + c1) * (2 * cov + c2)) / ((mx[i] ** 2 + my[i] ** 2 + c1) * (vx + vy + c2));
      ++count;
    }
  }
  return count ? sum / count : NaN;
}
