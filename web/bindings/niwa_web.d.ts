// The typed surface of the web module niwa_web (web/bindings/*.cpp), as the worker's handlers call
// it: every function and every session class with its methods. tests/browser/bindings_decl.test.mjs
// checks this file against the EMSCRIPTEN_BINDINGS blocks and against the built module, so a
// binding is not added, renamed or dropped without its declaration (after Filament's
// filament.d.ts, "must match the bindings").
//
// Conventions (web/bindings/error_record.h, buffers.h):
// - A method that can fail returns "" when it worked, else an ErrorRecord as JSON text.
// - *Json methods return JSON text; errors inside them are ErrorRecords.
// - buffers(group) returns {name: typed view into the WASM heap} (valid until the next call that
//   may allocate: copy at once), or null for an unknown group.

/** A core Status at the boundary: field is the state key it names ("" when none), message its one line. */
export interface ErrorRecord { ok: false; field: string; message: string; }
/** "" or an ErrorRecord as JSON text. */
export type ErrorText = string;
export type BufferViews = { [name: string]: Float32Array | Uint32Array | Int32Array | Uint16Array | Uint8Array } | null;

// ---- common_bindings.cpp: every study through core/compose/studies.h
/** [{name, unit}] of the studies. */
export function studiesJson(): string;
/** The study's parameter table (rows with key, symbol, unit, default, min, max, stage, help). */
export function tableJson(study: string): string;
/** The study's presets: a JSON array of {name, ...}. */
export function presetsJson(study: string): string;
/** {state, notices} of a share-link hash whose keys carry `prefix` ("" on a study's own page). */
export function decodeHash(study: string, hash: string, prefix: string): string;
/** {ok: true, hash} or an ErrorRecord. */
export function encodeHash(study: string, stateJson: string, prefix: string): string;

// ---- tree_state_bindings.cpp: the tree page's Save / Open
/** {ok: true, json} (the state file) or an ErrorRecord. */
export function stateFile(stateJson: string): string;
/** {ok: true, state} or an ErrorRecord. */
export function openStateFile(text: string): string;

// ---- texture_bindings.cpp
/** {width, height, pixels: Uint8Array} (RGBA, row 0 = v 0) of a procedural texture ('bark', 'barkNormal', 'leaf', 'flower'), or null. */
export function treeTexture(kind: string, leafShape: number, season: number, autumnColour: number, flowerColour: number, flowerForm: number, leafSpray: number): { width: number; height: number; pixels: Uint8Array } | null;

// ---- light_bindings.cpp: core/light/sun.h
/** The unit direction towards the sun, [x, y, z] (y up, azimuth from +x towards +z). */
export function sunDirection(altitudeDeg: number, azimuthDeg: number): [number, number, number];
/** The sun at a date, UTC time and place. */
export function sunAt(year: number, month: number, day: number, hoursUtc: number, latitudeDeg: number, longitudeDeg: number): { altitude: number; azimuth: number; direction: [number, number, number] };

// ---- tree_bindings.cpp: the tree thesis (ch. 2 growth, ch. 3 sway, ch. 4 hybrid rendering) over core/render/tree_run
export class TreeSession {
  constructor(stateJson: string);
  error(): ErrorText;
  years(): number;
  year(): number;
  done(): boolean;
  hash(): string;
  /** TreeRun::Update, as JSON text: {ok: true, stages: ('grow'|'mesh'|'sway'|'view')[]} (the stages
   * re-done; "grow": growYear() and buildMesh() again) or an ErrorRecord. */
  update(stateJson: string): string;
  buffers(group: string): BufferViews;
  growYear(): boolean;
  buildMesh(): ErrorText;
  statsJson(): string;
  buildGlb(): ErrorText;
  lookJson(): string;
  buildLodGlb(maxTriangles: number, lod: boolean): ErrorText;
  buildSwayGlb(fps: number): ErrorText;
  paramsJson(): string;
  swayNodes(): number;
  swayStart(): ErrorText;
  swayStartAt(origins: number[]): ErrorText;
  swayInstances(): number;
  swayStep(steps: number): number;
  swayDt(): number;
  swayStepsPerTick(): number;
  swaySpeed(): number;
  swayDuration(): number;
  swayWindSpeed(): number;
  buildHybrid(): ErrorText;
  atlasSize(): number;
  renderMode(): number;
  hybridView(ex: number, ey: number, ez: number, tx: number, ty: number, tz: number, fovY: number, width: number, height: number): string;
  hybridViewSlot(slot: number, ex: number, ey: number, ez: number, tx: number, ty: number, tz: number, fovY: number, width: number, height: number): string;
  /** The bark the state's rows bark, bark_model ask for on the grown tree (core/compose/bark_on_tree's GrowTreeBark): "" or an ErrorRecord as text. */
  dressBark(): string;
  barkDressed(): boolean;
  /** {width, height, pixels, digest} of the dressed bark's "bark" | "barkNormal" map, or null. */
  barkTexture(kind: string): { width: number; height: number; pixels: Uint8Array; digest: string } | null;
  barkJson(): string;
  delete(): void;
}

// ---- ivy_bindings.cpp: paper 004 over core/ivy/ivy_run
/** The built-in scenes: [{name, description, free, triangles, seeds: [{name, pos}]}]. */
export function ivyScenesJson(): string;
/** {width, height, pixels: Uint8Array}: the leaf texture the .glb embeds. */
export function ivyLeafTexture(): { width: number; height: number; pixels: Uint8Array };

export class IvyLab {
  constructor();
  loadScene(name: string): ErrorText;
  loadTree(preset: string, years: number): ErrorText;
  loadMesh(bytes: string, name: string): ErrorText;
  supportJson(): string;
  grow(stateJson: string): ErrorText;
  statsJson(): string;
  hash(): string;
  steps(): number;
  modelJson(): string;
  lstring(): string;
  buildGlb(withSupport: boolean): ErrorText;
  exportCheck(format: string, withSupport: boolean): ErrorText;
  rayCast(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number): string;
  setProgress(fn: (stage: string, done: number, total: number) => void): void;
  buffers(group: string): BufferViews;
  delete(): void;
}

// ---- terrain_bindings.cpp: paper 002 over core/terrain/terrain_run
/** [{name, source, points, d, dh, h0}] of the built-in seed contours. */
export function terrainSeedsJson(): string;
/** {points, repaired, loops_removed, method} of a drawn contour, or an ErrorRecord naming "contour". */
export function terrainRepairContour(pointsJson: string): string;
/** {points, elevation?} of a contour file's text, or an ErrorRecord naming "contour". */
export function terrainParseContour(text: string): string;

export class TerrainLab {
  constructor();
  grow(stateJson: string): ErrorText;
  statsJson(): string;
  timingsJson(): string;
  hash(): string;
  stateJson(): string;
  boundsJson(): string;
  build(format: string): ErrorText;
  buffers(group: string): BufferViews;
  delete(): void;
}

// ---- moss_bindings.cpp: Nomura 2010 over core/moss/moss_run
/** The built-in scenes as `niwa moss scenes` lists them. */
export function mossScenesJson(): string;

export class MossLab {
  constructor();
  setProgress(fn: ((stage: string, done: number, total: number) => void) | null): void;
  grow(stateJson: string): ErrorText;
  /** A dropped .glb/.gltf/.obj (Draco decoded): kept for growOnMesh; errors name "mesh". */
  loadMesh(bytes: string, name: string): ErrorText;
  /** grow on the mesh loadMesh read (stats: scene "mesh" and its name). */
  growOnMesh(stateJson: string): ErrorText;
  /** Takes the mesh another lab read (shared, not read again): the A/B view's second run. */
  shareMesh(other: MossLab): void;
  /** {name, triangles} of the loaded mesh, or {}. */
  meshJson(): string;
  statsJson(): string;
  hash(): string;
  stateJson(): string;
  boundsJson(): string;
  /** "land": positions, normals, coverage, irradiance, geology, T_s, rh_s, theta, fitness; "mosses": positions, normals, species, birth, death, cell, on_moss; "photons": positions, depth (the last day's); "download": bytes (of the last build). */
  buffers(group: string): BufferViews;
  /** "glb" | "json": the bytes `niwa moss grow --out moss.glb|moss.json` writes for the last run, into buffers("download"); errors name "download". */
  build(format: string): ErrorText;
  delete(): void;
}

// ---- garden_bindings.cpp: issue 33 over core/compose/garden_run
/** The garden table as the panel reads it (the compose registry has no garden row). */
export function gardenTableJson(): string;
/** The garden's wind rows (the tree table's "wind" group but gust_on) as the panel reads a table, each default the garden's. */
export function gardenWindTableJson(): string;
/** {state (GardenStateJson), notices} of the default garden with the link's keys. */
export function gardenDecodeJson(hash: string): string;

export class GardenLab {
  constructor();
  /** fn(stage, done, total) after every year of a grow. */
  setProgress(fn: ((stage: string, done: number, total: number) => void) | null): void;
  /** A dropped .glb/.gltf/.obj's bytes (Draco decoded by the page), kept by `name` for the state's mesh objects and mesh ground; errors name "mesh". */
  loadMesh(bytes: Uint8Array, name: string): ErrorText;
  /** The triangles of the last mesh loadMesh read. */
  meshTriangles(): number;
  /** An opened PNG, role "heightmap" (a grey PNG, 16-bit kept) or "mask", decoded in the core and kept by `name` for the state's heightmap ground or mask; errors name "ground.file" or "mask". */
  loadImage(role: string, bytes: Uint8Array, name: string): ErrorText;
  /** {role, name, width, height, bit_depth, colour_type} of the last image loadImage kept. */
  imageJson(): string;
  /** The garden state JSON (GardenStateJson) over the default garden, checked and started (every year recorded); nothing grown yet. */
  start(stateJson: string): ErrorText;
  /** One garden year of the started garden: "more", "grown" (the run kept, its buffers filled) or an error record. */
  step(): string;
  /** Where the last grow's time went in the worker, ms: {ground, plant, moss_start, growth, moss, records, ivy, bark, mesh}. */
  phasesJson(): string;
  /** How many grows this lab started. */
  grows(): number;
  /** grows() when the run kept was grown. */
  runGrows(): number;
  /** {years, recorded: [years], stopped_by, record_bytes, bytes: [per year], mosses: [per year]}. */
  yearsJson(): string;
  /** Fills buffers("year") with the recorded year's trees and moss light; errors name "year". */
  /** Distinct tree `group`'s simulated bark map ("bark" base colour or "barkNormal"), the garden .glb's; null when it wears the procedural bark. */
  barkTexture(group: number, kind: string): { width: number; height: number; pixels: Uint8Array; digest: string } | null;
  showYear(year: number): ErrorText;
  /** Blow: the wind rows ({"wind_speed": 5, ...}; "{}": the state's wind, the front entering its upwind edge at t = 0) over the last grown year's trees, one sway simulator a tree; fills buffers("skin") and buffers("wind") at rest; errors name the row, "wind" or the page budget's limit. */
  blowStart(windJson: string): ErrorText;
  /** Every tree `steps` (at most 64) time steps further; fills buffers("wind"); returns the wind's time (s). */
  blowStep(steps: number): number;
  /** The state's wind rows ({"wind_speed": 12, ...}) set on the last run without regrowing (hash() and stateJson() carry them); errors name "wind.<key>". */
  setWind(windJson: string): ErrorText;
  blowStop(): void;
  blowDt(): number;
  blowDuration(): number;
  /** Steps one worker tick may take (the page sway's rules over every tree). */
  blowStepsPerTick(): number;
  /** The share of real time the sway keeps (at most 1). */
  blowSpeed(): number;
  /** The wind's speed (m/s) at the garden's centre now. */
  blowWindSpeed(): number;
  /** Pose blocks of every copy (0: not blowing). */
  blowBlocks(): number;
  /** Each distinct tree's hybrid scene (thesis ch. 4) of garden year `year`: "" or an error record. */
  hybridBuild(year: number): string;
  /** Distinct trees with a hybrid scene (0 before hybridBuild). */
  hybridGroups(): number;
  /** Group `group`'s sway node points (its pose block's length), 0 for no such group. */
  hybridNodes(group: number): number;
  /** Group `group`'s card-atlas geometry into "atlas.bark|leaves|flowers"; its atlas side (0: none). */
  hybridAtlas(group: number): number;
  /** Group `group`'s draw list ("cards", "lines") for a camera in its frame, hysteresis of `slot` (0..255), lines lit from (lx, ly, lz), their C_b the group's simulated bark's mean colour when `bark` (else the procedural brown), with their sway skin: "" or an error record naming "view". */
  hybridView(group: number, slot: number, ex: number, ey: number, ez: number, tx: number, ty: number, tz: number,
    fovY: number, width: number, height: number, lx: number, ly: number, lz: number, bark: boolean): string;
  statsJson(): string;
  hash(): string;
  stateJson(): string;
  /** {size, n, cell, relief, min, max, groups: [{name, species, seed, age, trees, shaded, crown}], trees: [{species, seed, age, pos, rot, hand, group}]}. */
  boundsJson(): string;
  /** "ground": positions, normals, indices, heights, moss_S; "objects": positions, normals, indices, kind, birth; "trees": positions, normals, indices, part, ranges, instances; "year": the trees' six and moss_S of showYear's year; "skin": joints, weights, blocks (after blowStart); "wind": poses; "download": bytes (of the last build). */
  buffers(group: string): BufferViews;
  /** "glb" | "svg" | "json" | "heightmap": the run's Export bytes into buffers("download"); errors name "download". */
  build(format: string): ErrorText;
  delete(): void;
}

// ---- bark_bindings.cpp: paper 003 (Hirota, Kato, Kaneko) over core/bark/bark_run
export class BarkLab {
  constructor();
  /** fn(stage, done, total) every 256 steps of a grow; a false return cancels it. */
  setProgress(fn: ((stage: string, done: number, total: number) => boolean | void) | null): void;
  /** The state's checks and estimate against the page's budget, nothing grown: "" or the error record. */
  check(stateJson: string): ErrorText;
  grow(stateJson: string): ErrorText;
  statsJson(): string;
  hash(): string;
  stateJson(): string;
  cyclesCsv(): string;
  /** {n_r, n_h, circumference, height, radius, steps, steps_per_cycle, cycles, springs, map?}. */
  boundsJson(): string;
  /** A map's PNG bytes ("base_colour", "normal", "height", "orm"), or null with lastError(). */
  mapPng(map: string): Uint8Array | null;
  /** The trunk segment's .glb (`niwa bark grow --url HASH --out trunk.glb`), or null with lastError(). */
  glb(): Uint8Array | null;
  lastError(): ErrorText;
  /** "tile": positions, stretch, broken, layer, peel; "springs": positions, broken; "maps": base_colour, normal, orm. */
  buffers(group: string): BufferViews;
  delete(): void;
}
