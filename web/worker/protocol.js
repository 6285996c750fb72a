// The worker protocol as JSDoc types: every message between the pages (web/shell/worker_client.js)
// and the worker (web/worker/worker.js and its per-study handlers). Init, then update messages;
// buffers are transferred, never copied twice. Type-only module: it exports nothing at run time
// but the list of message types, which the router checks.
// Does not: validate values (the core does; the worker answers {type:'error'} with its line).

/**
 * Fields of every message. `client` (any string, default 'app') keeps clients apart: a newer
 * superseding request (update) of a client drops the older one of THE SAME client. `study`
 * picks the handler (default 'tree'). Replies echo `id` and `client`.
 * @typedef {{type: string, id?: number, client?: string, study?: string}} Envelope
 */

/**
 * Tree state as the page sends it: anything missing takes the preset's values; the core checks it.
 * @typedef {{preset?: string, seed?: number|string, years?: number|string,
 *   params?: Object<string, number|string>, prunes?: string[], camera?: string}} TreeStateJson
 */

/**
 * @typedef {Envelope & {type: 'init', hash?: string}} InitMessage
 *   -> ReadyMessage
 * @typedef {Envelope & {type: 'ready', paramTable: ParamRow[], presets: Object[],
 *   decoded: {state: TreeStateJson, notices: string[], shadows: 'on'|'off'}}} ReadyMessage
 * @typedef {{key: string, symbol: string, unit: string, default: number, min: number, max: number,
 *   integer: boolean, group: string, group_title?: string, stage?: 'grow'|'mesh'|'sway'|'view',
 *   help: string}} ParamRow
 *
 * @typedef {Envelope & {type: 'decode', hash: string}} DecodeMessage
 *   -> {type: 'decoded', id, client, state: TreeStateJson, notices: string[], shadows: 'on'|'off'}
 *   (the link's shadows= is the page's field, taken out before the core decodes the hash; a bad
 *   value is a notice; an older link's bark=sim|procedural is read as the row bark=1|0)
 */

/**
 * Grows state.years years, or only `until` years when given (the year scrubber). `stage` (sent by
 * web/shell/study_controller.js: the earliest stage the page's edits touched; none: 'grow'):
 * with 'mesh', 'sway' or 'view' it is a restage: the same tree (the grow-stage fields equal the
 * client's last tree) with a new state; the session's update (core TreeRun::Update) re-does the
 * earliest stage whose rows changed and the ones after it (mesh: re-dressed; sway: re-skinned;
 * view: the hybrid scene rebuilt) and the worker answers without growing (TreeMessage grown:
 * false, with the stages re-done). When the tree would differ (or none was grown) it grows.
 * The state's rows `bark` 1 and `bark_model` 2|4 (the Bark choice): the tree's bark is the bark
 * study's maps (TreeSession.dressBark; a refusal is an error with control 'bark', the tree sent
 * procedural); they are view rows, so a change of them alone restages the tree grown (dressed or
 * undressed, not regrown).
 * @typedef {Envelope & {type: 'update', state: TreeStateJson, until?: number,
 *   stage?: 'grow'|'mesh'|'sway'|'view'}} UpdateMessage
 *   -> HashMessage (state accepted), ProgressMessage (after each year), TreeMessage
 *
 * @typedef {Envelope & {type: 'hash', hash: string}} HashMessage
 * @typedef {Envelope & {type: 'stateFile', save?: TreeStateJson, open?: string}} StateFileMessage
 *   -> {type: 'stateFile', json: string} (save: the state file) | {type: 'stateFile', state:
 *   TreeStateJson} (open: the file read) | an error naming the field (web/tree/state_file.js)
 * @typedef {Envelope & {type: 'progress', year: number, years: number}} ProgressMessage
 */

/**
 * Mesh parts as typed views of the exact length (their buffers transferred, and maybe larger: a
 * part's size is the view's byteLength). The buffers are the ones the client handed back with
 * 'recycle' when they fit, else fresh (web/worker/transfer.js TransferPool); the reply's `buffers`
 * counts them {reused, fresh, dropped}; the textures' pixels ('textures.<kind>') and the hybrid atlas
 * ('atlas.<part>.*') go the same way (web/shell/worker_client.js treeExtras). Every part has joints (Uint32) and weights (Float32)
 * per vertex: the sway skin of core/sway/skin.h; leaves have uvs; bark has branchIds per vertex and
 * branchParents per branch; every part has occlusion (Float32 per vertex, 0-1: the crown's ambient
 * occlusion, core/tree/crown_occlusion.h) when the mesh was built.
 * @typedef {{positions: ArrayBuffer, normals: ArrayBuffer, indices: ArrayBuffer, joints: ArrayBuffer,
 *   weights: ArrayBuffer, uvs?: ArrayBuffer, branchIds?: ArrayBuffer, branchParents?: ArrayBuffer,
 *   occlusion?: ArrayBuffer}} MeshPart
 * With render_mode 1, hybrid holds the clip-space triangles that paint the card atlas (thesis 4.2.1).
 * @typedef {{atlasSize: number, bark: MeshPart, leaves: MeshPart, flowers: MeshPart}} HybridAtlas
 * @typedef {Envelope & {type: 'tree', stats: Object, mesh: {bark: MeshPart, leaves: MeshPart,
 *   flowers: MeshPart}, hybrid: HybridAtlas|null, swayNodes: number, grown: boolean,
 *   stages: string[]|null, buffers: {reused: number, fresh: number}, workerMs: number|null, builtMs: number|null}}
 *   TreeMessage (workerMs: a grow's wall time in the worker, from its request to this message, the
 *   mesh's copies out of the heap included; builtMs: from its request to the mesh built)
 *   grown: false when the tree on screen was re-meshed, re-skinned or re-viewed (restage), not
 *   grown again; stages: then the stages core TreeRun::Update re-did ('mesh', 'sway', 'view').
 */

/**
 * The client's buffers back once they are on its GPU (tree: the mesh parts, 'sway.poses' of a pose,
 * 'cards.*' and 'lines.*' of a draw list, 'atlas.*' of a hybrid or motion atlas; ivy: stems, leaves, suckers, buds, 'support.*', and 'leafTexture.pixels', which any client's next copy may fill), as {"<part>.<name>": ArrayBuffer} (web/shell/worker_client.js recycle), transferred;
 * the next reply copies into them. No reply.
 * @typedef {Envelope & {type: 'recycle', buffers: Object<string, ArrayBuffer>}} RecycleMessage
 */

/**
 * Starts (play: true, from rest) or stops the sway of the client's last tree in its state's wind.
 * origins (the grove): 3 numbers (metres) per instance, each swayed in the wind at its place;
 * poses then holds instances × swayNodes × 16 floats. clock: sways started with one name share a
 * wall clock. The simulation follows the wall clock (steps of dt, at most 8 per tick) and loops
 * at the wind's duration; the next pose is sent after the client's poseDone.
 * @typedef {Envelope & {type: 'wind', play: boolean, origins?: number[], clock?: string}} WindMessage
 *   -> PoseMessage, one at a time
 * @typedef {Envelope & {type: 'poseDone'}} PoseDoneMessage
 * @typedef {Envelope & {type: 'pose', time: number, wind: number, instances: number, stepMs: number,
 *   poses: Float32Array, buffers: {reused: number, fresh: number}}} PoseMessage
 *   poses: a view of the exact length, into the buffer the client handed back when it fits
 */

/**
 * Hybrid mode, after a tree: eq. 4.1 selection with hysteresis against the client's last view (or
 * the slot's: 0..255, one draw list per slot, the grove's distance bands; slot and tag echoed).
 * @typedef {Envelope & {type: 'view', camera: {eye: number[], target: number[], fovY: number,
 *   width: number, height: number}, slot?: number, tag?: any}} ViewMessage
 *   -> {type: 'drawList', client, stats, cards: {positions, uvs, indices, joints, weights},
 *       lines: {positions, colors, widths, joints, weights}, buffers: {reused, fresh}, slot?, tag?}
 *       (views of the exact length into the client's returned buffers when they fit; transferred)
 * With motion: true (and atlas: true for the atlas), the same for a full-mode tree: its cheaper
 * representation while it moves (issue 16), -> {type: 'motionAtlas', client, hybrid, buffers:
 * {reused, fresh, dropped}} (as the tree message's hybrid, into the 'atlas.*' buffers the client
 * handed back when they fit: the page recycles them once painted) when asked, then {type: 'drawList', motion: true, ...}; a scene that cannot
 * be built -> {type: 'error', client, control: 'motion', message}.
 */

/**
 * A client's end (web/shell/worker_client.js close()): every study's handler loaded so far lets
 * the client's sessions and returned buffers go (its close(client)); the router answers.
 * @typedef {Envelope & {type: 'close'}} CloseMessage
 *   -> {type: 'closed', id, client, released: {<study>: {sessions: number, buffers: number}}}
 */

/**
 * Exports are one-off copies: the bytes are copied once out of the heap into a fresh buffer and
 * transferred; the page keeps them in its download's Blob (nothing is handed back).
 * @typedef {Envelope & {type: 'export', format: 'glb'|'json'}} ExportMessage
 *   -> {type: 'export', id, client, format, bytes: ArrayBuffer} (the client's last finished tree)
 * Any failure -> {type: 'error', id, client, message} (one line, naming the field and its range).
 * @typedef {Envelope & {type: 'error', message: string}} ErrorMessage
 */

/**
 * The ivy page and <niwa-ivy> (study: 'ivy', web/worker/ivy_handler.js). State: {preset, seed,
 * steps, scene ('tree': tree, tree_years), seed_points: "X,Y,Z;..", params}; ready also carries
 * `scenes` [{name, description, seeds}] and `trees` [{name, title, years}].
 * @typedef {Envelope & {type: 'update', state: Object, useMesh?: boolean}} IvyUpdateMessage
 *   -> SupportMessage without an id ({request: id}; when the scene or tree changed),
 *      ProgressMessage {stage: scene|tree|bvh|grow|read, done?, total?, text} (at most one per 100 ms),
 *      {type: 'ivy', stats, mesh: {stems, leaves, suckers: {positions, normals, indices, birth},
 *       buds: {positions, kind, birth}} (leaves also uvs: the .glb's TEXCOORD_0; typed views, as
 *       the tree's MeshPart, into the buffers the client handed back with 'recycle' when they fit),
 *       leafTexture?: {width, height, pixels: Uint8Array RGBA} (the .glb's leaf texture, in the
 *       client's first 'ivy' only; the page hands it back as 'leafTexture.pixels' once uploaded,
 *       and any client's returned one carries the next client's copy: leafTextureBuffers
 *       {reused, fresh}), steps, hash, wallMs, buffers: {reused, fresh}}
 * @typedef {Envelope & {type: 'mesh', name: string, bytes: ArrayBuffer}} IvyMeshMessage
 *   -> {type: 'support', support: {name, dropped, free, triangles, bounds, seeds}, buffers:
 *       {positions, normals, indices} (views, into the 'support.*' buffers the client handed back
 *       when they fit), bufferCounts: {reused, fresh, dropped}}
 * @typedef {Envelope & {type: 'pick', origin: number[], direction: number[]}} IvyPickMessage
 *   -> {type: 'picked', hit: {hit, point?, normal?, distance?}}
 * @typedef {Envelope & {type: 'encode', state: Object}} IvyEncodeMessage -> {type: 'encoded', ok, hash} or {type: 'encoded', ok: false, field, message}
 * export: format 'glb' (withSupport?) | 'json' | 'lsys'.
 */

/**
 * The terrain page (study: 'terrain', web/worker/terrain_handler.js). State: {preset, builtin |
 * contour: [[x, y], ...], seed, params}; ready carries `paramTable`, `presets`, `seeds`, `decoded`.
 * @typedef {Envelope & {type: 'update', state: Object, repair?: boolean, statsAfter?: boolean}} TerrainUpdateMessage
 *   -> ProgressMessage, {type: 'terrain', stats, timings, buffers: {surface (no indices: the
 *       page builds them, web/terrain/grid_indices.js, from bounds.width × height), contours,
 *       summits; each a group of views into the buffers the client handed back when they fit),
 *       bufferCounts: {reused, fresh, dropped}, hash, state, bounds, repaired, parts: {repair,
 *       grow, stats, copy, state} (ms), wallMs}; with statsAfter: true its stats are null and {type: 'terrainStats', stats,
 *       statsMs} follows at once (the page: the surface is not kept waiting for the stats)
 * @typedef {Envelope & {type: 'recycle', buffers: Object<string, ArrayBuffer>}} TerrainRecycleMessage
 *   (no reply) the page's buffers as {"surface.positions", "contours.level", "summits.positions",
 *   ...: ArrayBuffer} (web/shell/worker_client.js recycle), transferred back: the surface once
 *   uploaded, the contours and summits once a newer mountain replaced them; the next update
 *   copies into them
 * @typedef {Envelope & {type: 'parseContour', name: string, text: string}} TerrainParseContourMessage
 *   -> {type: 'contourFile', name, points?, elevation?, error?}
 * export: format 'glb' | 'heightmap' | 'sidecar' | 'json' | 'geojson' | 'svg'.
 */
/**
 * The moss page (study: 'moss', web/worker/moss_handler.js). State: {preset, scene, days, seed,
 * params}; ready carries `paramTable`, `presets`, `scenes`, `decoded`.
 * @typedef {Envelope & {type: 'update', state: Object, useMesh?: boolean}} MossUpdateMessage
 *   (useMesh: grow on the mesh the client dropped, not the state's scene)
 *   -> ProgressMessage (after every day: stage 'grow', done, total days), {type: 'moss', stats (the
 *       CLI's `niwa moss grow --stats`, ms* fields included), hash, state, bounds: {min, max, cells,
 *       days, mosses_ever, mosses_alive, irradiance_max}, buffers: {land: {positions, normals,
 *       coverage, irradiance, geology, T_s, rh_s, theta, fitness}, mosses: {positions, normals, species, birth,
 *       death, cell, on_moss}, photons: {positions, depth}} (views into the
 *       buffers the client handed back when they fit), bufferCounts, growMs, wallMs}
 * @typedef {Envelope & {type: 'mesh', name: string, bytes: ArrayBuffer}} MossMeshMessage
 *   -> {type: 'meshLoaded', mesh: {name, triangles}} or an error naming "mesh" (the lab keeps the
 *       mesh for the updates with useMesh)
 * @typedef {Envelope & {type: 'recycle', buffers: Object<string, ArrayBuffer>}} MossRecycleMessage
 *   (no reply) the page's land and moss buffers back once on the GPU.
 */
/**
 * The garden page (study: 'garden', web/worker/garden_handler.js). State: the garden state JSON
 * (core/compose/garden_state.h GardenStateJson: {params, ground, objects, plants, mix}); ready
 * carries `paramTable` (the garden table), `windTable` (the tree table's rows of the garden's wind, its
 * defaults), `species` (the tree presets' names: the planting picker)
 * and `decoded` ({state, notices}: the default garden with the link's keys).
 * @typedef {Envelope & {type: 'update', state: Object}} GardenUpdateMessage
 *   -> ProgressMessage (after every year: stage 'grow', done, total years), {type: 'garden', stats
 *       (the run's StatsJson), statsText, hash, state, bounds: {size, n, cell, relief, min, max,
 *       groups: [{name, species, seed, age, trees, shaded, crown}], trees: [{species, seed, age,
 *       pos, rot, hand, group}]}, years: {years, recorded: [years], stopped_by, record_bytes,
 *       bytes: [per recorded year], mosses: [per recorded year]} (the years recorded as the clock
 *       ran), grows (the client's lab's grows so far), buffers: {ground: {positions, normals,
 *       indices, heights, moss_S}, objects: {positions, normals, indices, kind, birth (the garden
 *       year an ivy vertex grew in)}, trees: {positions, normals, indices, part, ranges,
 *       instances, uvs (with bark 1: the bark's uvs)}} (views into the buffers the client handed
 *       back when they fit), barks (per distinct tree {bark, barkNormal: {width, height, pixels,
 *       digest}} of its simulated bark, or null; [] with bark 0), bufferCounts, growMs, wallMs}
 * @typedef {Envelope & {type: 'year', year: number, grows?: number}} GardenYearMessage
 *   (the year scrubber: nothing grows) -> {type: 'gardenYear', year, grows, run, buffers: {year:
 *       {positions, normals, indices, part, ranges, instances, moss_S}} (that year's trees and moss
 *       light, from the run's record), bufferCounts, ms} or an error naming "year" (not recorded);
 *       a newer 'year' of the client drops an older one still queued (no reply); one whose
 *       `grows` is not the lab's run's (asked of the garden before a regrow) is answered {stale:
 *       true}; grows: the lab's grows so far, run: the grow of the garden kept
 * @typedef {Envelope & {type: 'mesh', name: string, bytes: ArrayBuffer}} GardenMeshMessage
 *   -> {type: 'meshLoaded', mesh: {name, triangles}} or an error naming "mesh": the mesh kept by
 *   name for the state's mesh objects ({kind: 'mesh', file: name}; at most 8 a client)
 *   Hybrid trees (web/garden/garden_hybrid.js): {type: 'hybrid', year, grows?} -> {type:
 *   'gardenAtlas', year, run, atlases: [per distinct tree {atlasSize, nodes, bark, leaves, flowers}:
 *   the card atlas's geometry, nodes its sway node points]} (an error with control: 'trees' when a scene cannot be built); {type:
 *   'hybridViews', tag, light, bark (default true: a tree in simulated bark colours its lines with
 *   its map's mean), views: [{group, slot (0..255), camera: {eye, target, fovY, width,
 *   height} in the tree's frame}]} -> {type: 'gardenDrawLists', tag, run, lists: [per view {group,
 *   slot, cards: {positions, uvs, indices, joints, weights}, lines: {positions, colors, widths,
 *   joints, weights}}]} (the skin: node points numbered as Blow's poses).
 * @typedef {Envelope & {type: 'wind', play: boolean, wind?: Object}} GardenWindMessage
 *   Blow (web/worker/garden_blow.js): play: true starts one sway simulator per planted tree of the
 *   last garden in the wind rows `wind` over the garden's defaults -> {type: 'blowing', run, skin:
 *   {joints, weights, blocks}, blocks, dt, speed, stepsPerTick} (the "trees" buffers' sway skin
 *   and each copy's first pose block) or an error with control: 'wind'; then {type: 'pose', time,
 *   wind, stepMs, speed, poses} one at a time, the next after the page's 'poseDone' (poses into
 *   the buffer handed back as 'recycle' {wind: {poses}}). play: false, an update or a 'year' stops it.
 *   The rows under `wind` go over the state's own wind rows (GardenStateJson's wind).
 * @typedef {Envelope & {type: 'windRows', wind: Object}} GardenWindRowsMessage
 *   The state's wind rows ({wind_speed, wind_dir, ...}: the ready message's windTable) set on the
 *   last garden without regrowing -> {type: 'gardenWindRows', hash, state} or an error naming
 *   "wind.<key>" with control: 'windRows'.
 * @typedef {Envelope & {type: 'image', role: 'heightmap'|'mask', name: string, bytes: ArrayBuffer}}
 *   GardenImageMessage -> {type: 'imageLoaded', image: {role, name, width, height, bit_depth,
 *   colour_type}} or an error naming "ground.file" (heightmap) or "mask": the PNG decoded in the
 *   core and kept by name for the state's heightmap ground ({kind: 'heightmap', file: name}) or
 *   mask (mask: name); at most 4 of each a client
 * export: format 'glb' | 'svg' | 'json' | 'heightmap' (the run's Export bytes).
 */
// (No list of message types here: each study's handler says which it answers, and the router
// refuses any other per study; a new study adds messages without touching this file.)
