"""Foliage cards (--leaves) imported into Blender (headless): two materials.

Run: blender -b --factory-startup --python blender_leaves_check.py -- FILE.glb...

For every file (an engine-ready GLB with --leaves and --lods), imports it with
Blender's glTF importer and checks every level object plant_<id>_LOD<i>: two
material slots, "plant" and "leaf"; the leaf material alpha-clipped (glTF
alphaMode MASK), drawn from both sides and textured with the embedded leaf
image (128 x 128, with alpha); the level's triangles with the plant material
as many as its extras' "triangles", and those with the leaf material two per
card of its extras' "leaves". A file named *colour*.glb (--colour) must also
carry a colour attribute (COLOR_0) on every level, in [0, 1], with more than
one colour on the plant's triangles. Exit status 1 on any failure.
"""
import sys
import warnings

import bpy
import numpy

# Blender 3.4's importer uses numpy's `np.bool`, removed in NumPy 1.24 (as in
# blender_pack_check.py).
with warnings.catch_warnings():
    warnings.simplefilter('ignore', FutureWarning)
    if not hasattr(numpy, 'bool'):
        numpy.bool = bool

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def check_colours(obj):
    """The level's colour attribute (the importer's name for COLOR_0): in
    range, and several colours on the plant's triangles (growth history)."""
    attributes = list(obj.data.color_attributes)
    if not check(attributes, f"{obj.name}: no colour attribute (COLOR_0 was not imported)"):
        return
    attribute = attributes[0]
    values = [tuple(round(c, 3) for c in d.color[:3]) for d in attribute.data]
    check(all(0.0 <= c <= 1.0 for v in values for c in v), f"{obj.name}: colours outside [0, 1]")
    plant = set()
    for polygon in obj.data.polygons:
        if polygon.material_index != 0:
            continue
        for loop in polygon.loop_indices:
            index = loop if attribute.domain == 'CORNER' else obj.data.loops[loop].vertex_index
            plant.add(values[index])
    check(len(plant) > 10, f"{obj.name}: {len(plant)} colours on the plant, not the growth history's many")
    print(f"blender: {obj.name}: colour attribute {attribute.name!r} ({attribute.domain}), "
          f"{len(plant)} colours on the plant")


def check_file(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    check(bpy.ops.import_scene.gltf(filepath=path) == {'FINISHED'}, f"{path}: the importer failed")
    levels = sorted((o for o in bpy.context.scene.objects if '_LOD' in o.name), key=lambda o: o.name)
    check(levels, f"{path}: no LOD objects")
    cards = []
    for obj in levels:
        names = [slot.material.name if slot.material else None for slot in obj.material_slots]
        if not check(names == ['plant', 'leaf'], f"{obj.name}: materials {names}, not plant and leaf"):
            continue
        leaf = obj.material_slots[1].material
        check(leaf.blend_method == 'CLIP', f"{obj.name}: leaf material blend {leaf.blend_method}, not CLIP (MASK)")
        check(not leaf.use_backface_culling, f"{obj.name}: leaf material culls back faces (not doubleSided)")
        images = [n.image for n in leaf.node_tree.nodes if n.type == 'TEX_IMAGE' and n.image]
        if check(len(images) == 1, f"{obj.name}: {len(images)} leaf images"):
            image = images[0]
            check(tuple(image.size) == (128, 128), f"{obj.name}: leaf image {tuple(image.size)}")
            alpha = list(image.pixels)[3::4]
            check(min(alpha) == 0.0 and max(alpha) == 1.0, f"{obj.name}: leaf image alpha {min(alpha)}..{max(alpha)}")
        by_material = [0, 0]
        for polygon in obj.data.polygons:
            by_material[polygon.material_index] += 1
        check(by_material[0] == obj.get('triangles'),
              f"{obj.name}: {by_material[0]} plant triangles, extras say {obj.get('triangles')}")
        check(by_material[1] == 2 * obj.get('leaves'),
              f"{obj.name}: {by_material[1]} leaf triangles, extras say {obj.get('leaves')} cards")
        cards.append(obj.get('leaves'))
        if 'colour' in path:
            check_colours(obj)
    print(f"blender {bpy.app.version_string}: {path}: {len(levels)} levels, two materials each "
          f"(plant; leaf: CLIP, two-sided, 128 x 128 texture with alpha), cards per level {cards}")


for glb in sys.argv[sys.argv.index('--') + 1:]:
    check_file(glb)
for failure in failures:
    print('FAIL:', failure)
sys.exit(1 if failures else 0)
