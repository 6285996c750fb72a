#!/usr/bin/env python3
"""Makes the terrain study's real seeds from real elevation models shipped in a Debian package.

Sources (Debian package python-matplotlib-data, which scripts/setup installs; matplotlib's sample
data under matplotlib's licence, /usr/share/doc/python-matplotlib-data/copyright):
  jacksboro  /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz: a USGS elevation grid
             of the Jacksboro fault, Tennessee (3 arc-second cells, 344 x 403, 236-1076 m); USGS
             elevation data is a work of the US federal government (public domain).
  topobathy  /usr/share/matplotlib/mpl-data/sample_data/topobathy.npz: topography and bathymetry of
             Vancouver Island, the Strait of Georgia and the Coast Mountains (2 arc-minute cells,
             91 x 120, 48.0-50.0 N, 126.0-122.0 W, -1437..2205 m): a second, coarser real DEM
             (cells of about 2.2 km) of younger, steeper mountains than the Appalachian ridge.

Writes (python3 standard library only: the .npz is a zip of .npy arrays):
  tests/data/terrain/<source>_dem.png + .json  the DEM resampled (bilinear) to square cells in local
      metres (x east from the west edge, y north from the south edge), in the format of
      `niwa terrain grow --heightmap` (16-bit grey, sidecar with min/max elevation, cell, origin)
  tests/data/terrain/<source>_<E>.json         the longest closed contour at elevation E (marching
      squares on that grid, Douglas-Peucker to a quarter cell), {"points", "elevation", "source"}
  core/terrain/seed_jacksboro.inc               (jacksboro only) the same points as a C++
      initialiser (the built-in seed)
Usage: scripts/terrain_dem_seed.py [jacksboro|topobathy] [ELEVATION=700]
       (a number first: jacksboro at that elevation, as before)
"""
import json, math, struct, sys, zipfile, zlib, os

SAMPLES = '/usr/share/matplotlib/mpl-data/sample_data/'
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def npy(z, name):
    data = z.read(name)
    hlen = struct.unpack('<H', data[8:10])[0]
    header = eval(data[10:10 + hlen].decode('latin1'))  # numpy's own header dict literal
    body = data[10 + hlen:]
    fmt = {'<i2': 'h', '<f4': 'f', '<f8': 'd'}[header['descr']]
    shape = header['shape']
    count = 1
    for s in shape:
        count *= s
    values = struct.unpack('<%d%s' % (count, fmt), body[:count * struct.calcsize(fmt)])
    return values, shape


def load(source):
    """The DEM as (elevations row-major with row 0 north, rows, cols, west, east, south, north in
    degrees of the grid's outer edges, a line naming it)."""
    if source == 'jacksboro':
        z = zipfile.ZipFile(SAMPLES + 'jacksboro_fault_dem.npz')
        elev, (rows, cols) = npy(z, 'elevation.npy')
        xmin, ymin = npy(z, 'xmin.npy')[0][0], npy(z, 'ymin.npy')[0][0]
        xmax, ymax = npy(z, 'xmax.npy')[0][0], npy(z, 'ymax.npy')[0][0]
        # The file's ymin (36.733) is its north edge and ymax (36.446) its south: row 0 is north.
        return (list(elev), rows, cols, min(xmin, xmax), max(xmin, xmax), min(ymin, ymax), max(ymin, ymax),
                'USGS DEM of the Jacksboro fault (matplotlib sample data jacksboro_fault_dem.npz, '
                'Debian python-matplotlib-data)')
    if source == 'topobathy':
        z = zipfile.ZipFile(SAMPLES + 'topobathy.npz')
        topo, (rows, cols) = npy(z, 'topo.npy')
        lon, _ = npy(z, 'longitude.npy')
        lat, _ = npy(z, 'latitude.npy')
        # Cell centres, latitude ascending (row 0 south): flipped so row 0 is north.
        dlon, dlat = (lon[-1] - lon[0]) / (cols - 1), (lat[-1] - lat[0]) / (rows - 1)
        elev = []
        for j in range(rows - 1, -1, -1):
            elev += topo[j * cols:(j + 1) * cols]
        return (elev, rows, cols, lon[0] - dlon / 2, lon[-1] + dlon / 2, lat[0] - dlat / 2, lat[-1] + dlat / 2,
                'topography and bathymetry of Vancouver Island and the Coast Mountains (matplotlib sample '
                'data topobathy.npz, Debian python-matplotlib-data)')
    sys.exit('terrain_dem_seed.py: source must be jacksboro or topobathy, not %r' % source)


def main():
    args = sys.argv[1:]
    source = 'jacksboro'
    if args and not args[0].replace('.', '', 1).isdigit():
        source = args.pop(0)
    level = float(args[0]) if args else 700.0
    elev, rows, cols, west, east, south, north, what = load(source)
    # Degrees to local metres (equirectangular at the mid latitude; WGS84 metres per degree).
    lat = math.radians((south + north) / 2)
    m_lat = 111132.92 - 559.82 * math.cos(2 * lat) + 1.175 * math.cos(4 * lat)
    m_lon = 111412.84 * math.cos(lat) - 93.5 * math.cos(3 * lat)
    width_m, height_m = (east - west) * m_lon, (north - south) * m_lat
    cx, cy = width_m / cols, height_m / rows  # the source cells (row 0 north, as matplotlib shows it)
    cell = round(min(cx, cy), 3)
    W, H = int(width_m / cell), int(height_m / cell)

    def src(i, j):
        return elev[min(rows - 1, max(0, j)) * cols + min(cols - 1, max(0, i))]

    grid = []
    for j in range(H):
        y = (j + 0.5) * cell / cy - 0.5
        j0 = math.floor(y); fy = y - j0
        for i in range(W):
            x = (i + 0.5) * cell / cx - 0.5
            i0 = math.floor(x); fx = x - i0
            top = src(i0, j0) * (1 - fx) + src(i0 + 1, j0) * fx
            bot = src(i0, j0 + 1) * (1 - fx) + src(i0 + 1, j0 + 1) * fx
            grid.append(top * (1 - fy) + bot * fy)
    lo, hi = min(grid), max(grid)

    # 16-bit grey PNG (PNG spec: IHDR, IDAT with filter 0 rows, IEND) and its sidecar.
    meta = {'format': 'niwa terrain heightmap', 'width': W, 'height': H, 'min_elevation': lo,
            'max_elevation': hi, 'cell_size': cell, 'origin': {'x': 0.0, 'y': H * cell},
            'origin_is': 'north-west corner of pixel (0, 0); x east, y north, metres; row 0 is north',
            'elevation': 'min_elevation + sample / 65535 * (max_elevation - min_elevation)',
            'source': what + ', resampled bilinear to square cells'}
    raw = bytearray()
    for j in range(H):
        raw.append(0)
        for i in range(W):
            v = round((grid[j * W + i] - lo) / (hi - lo) * 65535)
            raw += struct.pack('>H', v)

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, H, 16, 0, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + chunk(b'IEND', b'')
    out = os.path.join(ROOT, 'tests', 'data', 'terrain')
    os.makedirs(out, exist_ok=True)
    open(os.path.join(out, source + '_dem.png'), 'wb').write(png)
    open(os.path.join(out, source + '_dem.json'), 'w').write(json.dumps(meta, indent=2) + '\n')

    # Marching squares over the cell centres; segments chained into closed rings.
    def pos(i, j):
        return ((i + 0.5) * cell, (H - j - 0.5) * cell)

    def cross(a, b):  # the point on the grid edge a-b (node ids) where the surface meets `level`
        (ia, ja), (ib, jb) = a, b
        va, vb = grid[ja * W + ia], grid[jb * W + ib]
        t = (level - va) / (vb - va)
        pa, pb = pos(ia, ja), pos(ib, jb)
        return (pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]))

    nxt = {}
    for j in range(H - 1):
        for i in range(W - 1):
            c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]  # clockwise on screen
            up = [grid[q[1] * W + q[0]] >= level for q in c]
            edges = [(c[k], c[(k + 1) % 4]) for k in range(4)]
            crossing = [k for k in range(4) if up[k] != up[(k + 1) % 4]]
            if not crossing:
                continue
            if len(crossing) == 4:  # saddle: the centre decides
                centre = sum(grid[q[1] * W + q[0]] for q in c) / 4 >= level
                pairs = [(0, 1), (2, 3)] if centre != up[0] else [(3, 0), (1, 2)]
            else:
                pairs = [tuple(crossing)]
            for k0, k1 in pairs:
                # Orient so the high side is on the left (counter-clockwise around summits).
                e0, e1 = edges[k0], edges[k1]
                key0, key1 = tuple(sorted(e0)), tuple(sorted(e1))
                a_high = up[k0]  # edge k0 goes from corner k0 (high?) to k0+1
                if a_high:
                    nxt[key1] = key0
                else:
                    nxt[key0] = key1
    rings, seen = [], set()
    for start in list(nxt):
        if start in seen:
            continue
        ring, k = [], start
        while k in nxt and k not in seen:
            seen.add(k); ring.append(k); k = nxt[k]
        if k == start and len(ring) > 8:
            rings.append([cross(*e) for e in ring])

    def area(r):
        return sum(r[k][0] * r[(k + 1) % len(r)][1] - r[(k + 1) % len(r)][0] * r[k][1] for k in range(len(r))) / 2
    rings = [r if area(r) > 0 else r[::-1] for r in rings]
    ring = max(rings, key=lambda r: abs(area(r)))

    def dp(points, tol):  # Douglas-Peucker on a closed ring (split at the farthest pair)
        def simplify(pts):
            a, b = pts[0], pts[-1]
            best, at = -1, 0
            for k in range(1, len(pts) - 1):
                p = pts[k]
                ex, ey = b[0] - a[0], b[1] - a[1]
                L = math.hypot(ex, ey) or 1e-12
                d = abs(ex * (a[1] - p[1]) - ey * (a[0] - p[0])) / L
                if d > best:
                    best, at = d, k
            if best <= tol:
                return [a, b]
            return simplify(pts[:at + 1])[:-1] + simplify(pts[at:])
        far = max(range(len(points)), key=lambda k: math.dist(points[0], points[k]))
        first = simplify(points[:far + 1])
        second = simplify(points[far:] + [points[0]])
        return first[:-1] + second[:-1]
    simple = [(round(x, 2), round(y, 2)) for x, y in dp(ring, cell / 4)]
    name = '%s_%d' % (source, level)
    if source == 'jacksboro':  # the text the built-in seed has always carried
        line = ('the %g m contour of the USGS Jacksboro fault DEM (matplotlib sample data, Debian '
                'python-matplotlib-data; public domain USGS data), marching squares on %g m cells, '
                'Douglas-Peucker %g m; %d points; scripts/terrain_dem_seed.py' %
                (level, cell, cell / 4, len(simple)))
    else:
        line = ('the %g m contour of the %s, marching squares on %g m cells, Douglas-Peucker %g m; %d '
                'points; scripts/terrain_dem_seed.py %s %g' % (level, what, cell, cell / 4, len(simple), source, level))
    seed = {'points': [list(p) for p in simple], 'elevation': level, 'source': line}
    open(os.path.join(out, name + '.json'), 'w').write(json.dumps(seed) + '\n')
    if source == 'jacksboro':
        inc = ('// Generated by scripts/terrain_dem_seed.py %g: %s.\n' % (level, line))
        inc += '\n'.join('{%r, %r},' % p for p in simple) + '\n'
        open(os.path.join(ROOT, 'core', 'terrain', 'seed_jacksboro.inc'), 'w').write(inc)
    print('%s: %d x %d cells of %g m, %g..%g m; %d closed rings at %g m, the largest %d -> %d points, '
          'area %.0f m^2' % (name, W, H, cell, lo, hi, len(rings), level, len(ring), len(simple), area(ring)))


main()
