#!/usr/bin/env python3
"""Opens a .glb in Blender's glTF importer (background mode) and renders a picture: the check of
docs/lod-export.md "Which file for which engine". Prints one IMPORT line (objects, meshes with
vertices / polygons / edges, triangles, materials, armatures and bones, actions, loose edges, i.e.
glTF LINES) and writes a Cycles (CPU, 8 samples) render framed on the meshes; LOD siblings are
spread along x. Does not: check anything by itself (read its line and look at the picture).

Run: blender -b -P scripts/blender_look.py -- in.glb out.png [oblique]   (Debian: apt-get install blender)
With `oblique` the camera looks down at 40 degrees (a garden: wide and flat), else from the side.
"""
import sys, math, bpy, mathutils
import numpy
# Debian blender 3.4.1 with numpy >= 1.24: its glTF importer still uses np.bool (removed alias).
if not hasattr(numpy, "bool"):
    numpy.bool = bool
args = sys.argv[sys.argv.index('--') + 1:]
src, out = args[0], args[1]
oblique = len(args) > 2 and args[2] == 'oblique'
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=src)
objs = list(bpy.context.scene.objects)
meshes = [o for o in objs if o.type == 'MESH']
arms = [o for o in objs if o.type == 'ARMATURE']
tris = sum(sum(len(p.vertices) - 2 for p in o.data.polygons) for o in meshes)
print('IMPORT', src, 'objects', len(objs), 'meshes', [(o.name, len(o.data.vertices), len(o.data.polygons), len(o.data.edges)) for o in meshes][:6],
      'triangles', tris, 'materials', sorted({m.name for o in meshes for m in o.data.materials if m}),
      'armatures', [(a.name, len(a.data.bones)) for a in arms], 'actions', [(a.name, len(a.fcurves), a.frame_range[:]) for a in bpy.data.actions][:3],
      'loose edges', sum(1 for o in meshes for e in o.data.edges if e.is_loose), 'uv/attrs', [list(o.data.attributes.keys()) for o in meshes][:1])
# LOD siblings share one spot: spread them along x to see each.
lods = sorted([o for o in objs if '_LOD' in o.name and o.parent is None], key=lambda o: o.name)
if len(lods) > 1:
    for k, o in enumerate(lods):
        o.location.x += k * 12.0
bpy.context.view_layer.update()
lo = mathutils.Vector((1e9, 1e9, 1e9)); hi = -lo
for o in meshes:
    for c in o.bound_box:
        w = o.matrix_world @ mathutils.Vector(c)
        lo = mathutils.Vector(map(min, lo, w)); hi = mathutils.Vector(map(max, hi, w))
centre = (lo + hi) / 2; size = max(hi - lo)
cam = bpy.data.objects.new('cam', bpy.data.cameras.new('cam'))
bpy.context.scene.collection.objects.link(cam)
if oblique:
    cam.location = centre + mathutils.Vector((0, -0.95 * size, 0.8 * size))
    cam.rotation_euler = (math.radians(50), 0, 0)
else:
    cam.location = centre + mathutils.Vector((0, -1.9 * size, 0.15 * size))
    cam.rotation_euler = (math.radians(86), 0, 0)
bpy.context.scene.camera = cam
sun = bpy.data.objects.new('sun', bpy.data.lights.new('sun', 'SUN'))
sun.data.energy = 3.0; sun.rotation_euler = (math.radians(40), math.radians(20), math.radians(30))
bpy.context.scene.collection.objects.link(sun)
world = bpy.data.worlds.new('w'); bpy.context.scene.world = world
world.use_nodes = True; world.node_tree.nodes['Background'].inputs[0].default_value = (0.8, 0.85, 0.95, 1)
s = bpy.context.scene
s.render.engine = 'CYCLES'; s.cycles.device = 'CPU'; s.cycles.samples = 8; s.cycles.use_denoising = False
s.render.resolution_x = 640 if len(lods) > 1 else 400; s.render.resolution_y = 400
s.render.filepath = out
bpy.ops.render.render(write_still=True)
print('RENDERED', out)
