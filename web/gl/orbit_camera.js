// Orbit camera: yaw/pitch/distance around a target; orbit, pan and zoom by mouse, wheel, touch and keys.

const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (v) => {
  const l = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / l, v[1] / l, v[2] / l];
};

export class OrbitCamera {
  constructor() {
    this.yaw = OrbitCamera.DEFAULT_YAW;      // radians around +y
    this.pitch = OrbitCamera.DEFAULT_PITCH;  // radians above the horizon
    this.distance = 10;     // metres
    this.target = [0, 2, 0];
    this.fov = (45 * Math.PI) / 180;
    this.near = 0.05;
    this.far = 500;
  }

  // Frames an axis-aligned box {min:[x,y,z], max:[x,y,z]} (metres), keeping yaw and pitch;
  // margin > 1 leaves room around it.
  frame(bounds, margin = 1.02) {
    const min = bounds.min, max = bounds.max;
    const size = [max[0] - min[0], max[1] - min[1], max[2] - min[2]];
    const radius = Math.max(0.25, 0.5 * Math.hypot(size[0], size[1], size[2]));
    this.target = [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2];
    this.distance = (radius / Math.sin(this.fov / 2)) * margin;
    this.far = Math.max(100, this.distance * 20);
    this.near = Math.max(0.01, this.distance / 1000);
  }

  // "yaw,pitch,distance,tx,ty,tz" for the share link's cam= field.
  toHash() {
    const r = (x, d) => String(Number(x.toFixed(d)));
    return [r(this.yaw, 4), r(this.pitch, 4), r(this.distance, 3), ...this.target.map((t) => r(t, 3))].join(',');
  }

  // Reads toHash()'s text; false (camera unchanged) unless it holds six finite numbers.
  fromHash(text) {
    const v = String(text || '').split(',').map(Number);
    if (v.length !== 6 || !v.every(Number.isFinite)) return false;
    this.yaw = v[0];
    this.pitch = clamp(v[1], -0.1, 1.5);
    this.distance = clamp(v[2], 0.2, 400);
    this.target = v.slice(3);
    this.far = Math.max(100, this.distance * 20);
    this.near = Math.max(0.01, this.distance / 1000);
    return true;
  }

  // Default angle, framed on bounds: the "Reset view" button.
  reset(bounds) {
    this.yaw = OrbitCamera.DEFAULT_YAW;
    this.pitch = OrbitCamera.DEFAULT_PITCH;
    if (bounds) this.frame(bounds, 1.12);
  }

  // Moves the target across the view by a drag of (dx, dy) pixels on a view viewHeight pixels high.
  pan(dx, dy, viewHeight) {
    const perPixel = (2 * this.distance * Math.tan(this.fov / 2)) / Math.max(1, viewHeight);
    const sy = Math.sin(this.yaw), cy = Math.cos(this.yaw), sp = Math.sin(this.pitch), cp = Math.cos(this.pitch);
    const right = [cy, 0, -sy], up = [-sp * sy, cp, -sp * cy];
    for (let i = 0; i < 3; ++i) this.target[i] += (-dx * right[i] + dy * up[i]) * perPixel;
  }

  orbit(dYaw, dPitch) {
    this.yaw += dYaw;
    this.pitch = clamp(this.pitch + dPitch, -0.1, 1.5);
  }

  zoom(factor) {
    this.distance = clamp(this.distance * factor, 0.2, 400);
    this.far = Math.max(100, this.distance * 20);
    this.near = Math.max(0.01, this.distance / 1000);
  }

  position() {
    const cp = Math.cos(this.pitch);
    return [
      this.target[0] + this.distance * cp * Math.sin(this.yaw),
      this.target[1] + this.distance * Math.sin(this.pitch),
      this.target[2] + this.distance * cp * Math.cos(this.yaw),
    ];
  }

  viewProjection(aspect) {
    return multiply(perspective(this.fov, aspect, this.near, this.far), lookAt(this.position(), this.target, [0, 1, 0]));
  }

  // The ray through point (x, y) (CSS pixels from the top left) of a view `width` × `height` that
  // viewProjection(width / height) draws: {origin (the eye), direction (unit)}, in the camera's world.
  ray(x, y, width, height) {
    const ndcX = (2 * x) / width - 1, ndcY = 1 - (2 * y) / height;
    const eye = this.position(), target = this.target;
    const f = normalize([target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]]);
    const r = normalize(cross(f, [0, 1, 0]));
    const u = cross(r, f);
    const t = Math.tan(this.fov / 2), aspect = width / height;
    const dir = [0, 1, 2].map((i) => f[i] + r[i] * ndcX * t * aspect + u[i] * ndcY * t);
    return { origin: eye, direction: normalize(dir) };
  }

  // Drag / one-finger orbit; right- or Shift-drag / two-finger drag pan; wheel / pinch zoom;
  // arrows orbit, Shift+arrows pan, +/- zoom, on `element`.
  attach(element, onChange) {
    const pointers = new Map();
    let pinch = 0;
    let panning = false;
    const middle = () => {
      const [a, b] = [...pointers.values()];
      return { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
    };
    let mid = null;
    element.addEventListener('contextmenu', (e) => e.preventDefault());
    const spread = () => {
      const [a, b] = [...pointers.values()];
      return Math.hypot(a.x - b.x, a.y - b.y);
    };
    element.addEventListener('pointerdown', (e) => {
      element.setPointerCapture(e.pointerId);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      panning = e.button === 2 || e.shiftKey;
      if (pointers.size === 2) {
        pinch = spread();
        mid = middle();
      }
    });
    element.addEventListener('pointermove', (e) => {
      const p = pointers.get(e.pointerId);
      if (!p) return;
      if (pointers.size === 1) {
        if (panning) this.pan(e.clientX - p.x, e.clientY - p.y, element.clientHeight);
        else this.orbit(-(e.clientX - p.x) * 0.008, (e.clientY - p.y) * 0.008);
        p.x = e.clientX;
        p.y = e.clientY;
        onChange();
      } else if (pointers.size === 2) {
        p.x = e.clientX;
        p.y = e.clientY;
        const now = spread();
        if (pinch > 0 && now > 0) this.zoom(pinch / now);
        pinch = now;
        const m = middle();
        if (mid) this.pan(m.x - mid.x, m.y - mid.y, element.clientHeight);
        mid = m;
        onChange();
      }
    });
    const end = (e) => {
      pointers.delete(e.pointerId);
      pinch = pointers.size === 2 ? spread() : 0;
      mid = pointers.size === 2 ? middle() : null;
    };
    element.addEventListener('pointerup', end);
    element.addEventListener('pointercancel', end);
    element.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoom(Math.exp(clamp(e.deltaY, -200, 200) * 0.0015));
      onChange();
    }, { passive: false });
    element.addEventListener('keydown', (e) => {
      const step = 0.08, px = 30, h = element.clientHeight;
      const actions = e.shiftKey ? {
        ArrowLeft: () => this.pan(px, 0, h),
        ArrowRight: () => this.pan(-px, 0, h),
        ArrowUp: () => this.pan(0, px, h),
        ArrowDown: () => this.pan(0, -px, h),
      } : {
        ArrowLeft: () => this.orbit(step, 0),
        ArrowRight: () => this.orbit(-step, 0),
        ArrowUp: () => this.orbit(0, step),
        ArrowDown: () => this.orbit(0, -step),
        '+': () => this.zoom(0.9),
        '=': () => this.zoom(0.9),
        '-': () => this.zoom(1 / 0.9),
      };
      const action = actions[e.key];
      if (action) {
        e.preventDefault();
        action();
        onChange();
      }
    });
  }
}

OrbitCamera.DEFAULT_YAW = 0.6;
OrbitCamera.DEFAULT_PITCH = 0.25;

// Column-major 4x4 matrices (WebGL convention).
export function perspective(fov, aspect, near, far) {
  const f = 1 / Math.tan(fov / 2);
  const nf = 1 / (near - far);
  return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0]);
}

export function lookAt(eye, center, up) {
  let zx = eye[0] - center[0], zy = eye[1] - center[1], zz = eye[2] - center[2];
  let len = Math.hypot(zx, zy, zz) || 1;
  zx /= len; zy /= len; zz /= len;
  let xx = up[1] * zz - up[2] * zy, xy = up[2] * zx - up[0] * zz, xz = up[0] * zy - up[1] * zx;
  len = Math.hypot(xx, xy, xz) || 1;
  xx /= len; xy /= len; xz /= len;
  const yx = zy * xz - zz * xy, yy = zz * xx - zx * xz, yz = zx * xy - zy * xx;
  return new Float32Array([
    xx, yx, zx, 0,
    xy, yy, zy, 0,
    xz, yz, zz, 0,
    -(xx * eye[0] + xy * eye[1] + xz * eye[2]),
    -(yx * eye[0] + yy * eye[1] + yz * eye[2]),
    -(zx * eye[0] + zy * eye[1] + zz * eye[2]),
    1,
  ]);
}

export function multiply(a, b) {
  const out = new Float32Array(16);
  for (let c = 0; c < 4; ++c) {
    for (let r = 0; r < 4; ++r) {
      let s = 0;
      for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
      out[c * 4 + r] = s;
    }
  }
  return out;
}
