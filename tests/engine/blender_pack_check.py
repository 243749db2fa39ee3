"""A species pack imported into Blender (headless) has what the pack promises.

Run: blender -b --factory-startup --python blender_pack_check.py -- PACK_DIR...

For every pack and every species of its manifest.json, imports plant_<id>.glb with
Blender's glTF importer and checks: the object plant_<id>; its LOD children
plant_<id>_LOD0 .. (the count the manifest says was written, at most the options'), each mesh named
as its object; each level's
triangle count against the manifest; the height in metres (the manifest's,
and the --height asked for) with the lowest point at 0 and the foot at the
origin; the record in the object's custom properties (Blender keeps glTF
extras). Then imports scatter.glb: one object per species at distinct places.

_WIND: Blender 3.4's importer reads POSITION, NORMAL, TEXCOORD_n, COLOR_n,
JOINTS_n and WEIGHTS_n and drops every custom `_` attribute, so the imported
mesh cannot show it. What is checked then is what Blender's glTF reader
(io_scene_gltf2's glTFImporter) reads from the file: every level's primitive
has _WIND, four floats per vertex in [0, 1]. Where the imported mesh does
have it (a newer importer), its values are checked too. The script says
which check it made. Exit status 1 on any failure.
"""
import json
import math
import os
import sys
import warnings

import bpy
import numpy

# Blender 3.4's glTF importer uses numpy's `np.bool`, removed in NumPy 1.24
# (Debian 12 ships 1.24): every mesh import fails with AttributeError.
# glTF-Blender-IO fixed it for Blender 3.5 by writing `bool`
# (KhronosGroup/glTF-Blender-IO#1831, #1844); the same alias here.
with warnings.catch_warnings():
    warnings.simplefilter('ignore', FutureWarning)  # numpy 1.24 warns on the look-up itself
    if not hasattr(numpy, 'bool'):
        numpy.bool = bool

from io_scene_gltf2.io.imp.gltf2_io_binary import BinaryData
from io_scene_gltf2.io.imp.gltf2_io_gltf import glTFImporter

TOLERANCE = 1e-4  # metres: float32 positions of plants up to a few metres

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def import_glb(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.import_scene.gltf(filepath=path)
    check(result == {'FINISHED'}, f"{path}: the importer returned {result}")
    return {obj.name: obj for obj in bpy.context.scene.objects}


def read_gltf(path):
    """The file as Blender's glTF reader parses it."""
    gltf = glTFImporter(path, {'import_user_extensions': []})
    gltf.read()
    gltf.checks()
    return gltf


def world_bounds(objects):
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for obj in objects:
        for v in obj.data.vertices:
            p = obj.matrix_world @ v.co
            for k in range(3):
                lo[k] = min(lo[k], p[k])
                hi[k] = max(hi[k], p[k])
    return lo, hi


def check_file_wind(path, gltf, wind):
    """_WIND as Blender's reader reads it: VEC4 floats in [0, 1], one per vertex."""
    for mesh in gltf.data.meshes:
        for prim in mesh.primitives:
            if not wind:
                check('_WIND' not in prim.attributes, f"{path}: {mesh.name} has _WIND without --wind")
                continue
            if not check('_WIND' in prim.attributes, f"{path}: {mesh.name} has no _WIND attribute"):
                continue
            accessor = gltf.data.accessors[prim.attributes['_WIND']]
            check(accessor.type == 'VEC4' and accessor.component_type == 5126,
                  f"{path}: {mesh.name}'s _WIND is {accessor.type}/{accessor.component_type}, not VEC4 float")
            check(accessor.count == gltf.data.accessors[prim.attributes['POSITION']].count,
                  f"{path}: {mesh.name}'s _WIND has {accessor.count} values, not one per vertex")
            values = BinaryData.decode_accessor(gltf, prim.attributes['_WIND'])
            check(all(0.0 <= x <= 1.0 for row in values for x in row),
                  f"{path}: {mesh.name}'s _WIND leaves [0, 1]")


def imported_wind(mesh_objects, wind):
    """'imported' when the imported meshes carry _WIND (checked), 'dropped' when none does."""
    carried = [obj for obj in mesh_objects if '_WIND' in obj.data.attributes]
    for obj in carried:
        attribute = obj.data.attributes['_WIND']
        values = [x for item in attribute.data for x in getattr(item, 'vector', getattr(item, 'color', ()))]
        check(values and all(0.0 <= x <= 1.0 for x in values), f"{obj.name}: imported _WIND leaves [0, 1]")
    if not wind:
        return 'none asked'
    return 'imported' if carried else 'dropped'


def check_species(pack, manifest, species):
    options = manifest['options']
    name = 'plant_' + species['id']
    path = os.path.join(pack, species['file'])
    objects = import_glb(path)
    if not check(name in objects, f"{path}: no object {name} (objects: {sorted(objects)})"):
        return None
    root = objects[name]
    lods = options['lods']
    if lods > 0:  # the chain stops where a level cannot keep its distance bound (file-formats.md)
        written = species['lods_written']
        check(1 <= written <= lods, f"{path}: lods_written {written} with --lods {lods}")
        check(len(species['triangles']) == written, f"{path}: {len(species['triangles'])} triangle counts, {written} levels")
        check(root.get('lods_written') == written,
              f"{path}: {name}'s extras say lods_written {root.get('lods_written')}, the manifest {written}")
        lods = written
    if lods == 0:
        levels = [root]
    else:
        levels = [objects.get(f"{name}_LOD{i}") for i in range(lods)]
        check(all(levels), f"{path}: LOD objects missing: {sorted(objects)}")
        levels = [obj for obj in levels if obj is not None]
        check(sorted(child.name for child in root.children) == sorted(obj.name for obj in levels),
              f"{path}: {name}'s children are {[c.name for c in root.children]}")
        check(len(objects) == lods + 1, f"{path}: {len(objects)} objects, not {name} and {lods} LODs")
    for i, obj in enumerate(levels):
        check(obj.data.name == obj.name, f"{obj.name}: its mesh is named {obj.data.name}")
        polygons = obj.data.polygons
        check(all(len(p.vertices) == 3 for p in polygons), f"{obj.name}: not all triangles")
        check(len(polygons) == species['triangles'][i],
              f"{obj.name}: {len(polygons)} triangles in Blender, manifest says {species['triangles'][i]}")
    lo, hi = world_bounds(levels[:1])
    height = hi[2] - lo[2]
    check(abs(lo[2]) <= TOLERANCE, f"{name}: lowest point at z = {lo[2]}, not 0")
    check(abs(height - species['height_m']) <= TOLERANCE * max(1.0, height),
          f"{name}: {height} m tall in Blender, manifest says {species['height_m']}")
    if options['height_m'] is not None:
        check(abs(height - options['height_m']) <= TOLERANCE * max(1.0, height),
              f"{name}: {height} m tall, --height asked for {options['height_m']}")
    check(abs(lo[0] + hi[0]) < height and abs(lo[1] + hi[1]) < height,
          f"{name}: foot far from the origin (x {lo[0]}..{hi[0]}, y {lo[1]}..{hi[1]})")
    check(root.get('genome_hash') == species['genome_hash'], f"{name}: extras genome_hash {root.get('genome_hash')}")
    check(root.get('id') == species['id'], f"{name}: extras id {root.get('id')}")
    if 'cell' in species:
        check(root.get('cell') == species['cell'], f"{name}: extras cell {root.get('cell')}, manifest {species['cell']}")
    check_file_wind(path, read_gltf(path), options['wind'])
    return imported_wind(levels, options['wind'])


def check_scatter(pack, manifest):
    path = os.path.join(pack, manifest['scatter']['file'])
    gltf = read_gltf(path)
    used = gltf.data.extensions_used or []
    required = gltf.data.extensions_required or []
    check('EXT_mesh_gpu_instancing' in used, f"{path}: EXT_mesh_gpu_instancing not in extensionsUsed")
    check('EXT_mesh_gpu_instancing' not in required, f"{path}: EXT_mesh_gpu_instancing is required")
    check_file_wind(path, gltf, manifest['options']['wind'])
    objects = import_glb(path)
    places = set()
    for species in manifest['species']:
        name = 'plant_' + species['id']
        if not check(name in objects, f"{path}: no object {name}"):
            continue
        obj = objects[name]
        check(len(obj.data.polygons) == species['triangles'][0],
              f"{path}: {name} has {len(obj.data.polygons)} triangles, not LOD0's {species['triangles'][0]}")
        places.add(tuple(round(x, 4) for x in obj.matrix_world.translation))
    check(len(places) == len(manifest['species']), f"{path}: species share places: {sorted(places)}")
    meshes = [obj for obj in objects.values() if obj.type == 'MESH']
    return len(meshes)


def check_pack(pack):
    with open(os.path.join(pack, 'manifest.json')) as f:
        manifest = json.load(f)
    check(manifest['species'], f"{pack}: no species")
    wind = set()
    for species in manifest['species']:
        wind.add(check_species(pack, manifest, species))
    drawn = check_scatter(pack, manifest)
    print(f"blender {bpy.app.version_string}: {pack}: {len(manifest['species'])} species, "
          f"{manifest['options']['lods']} LODs each: names, triangles, height and extras checked; "
          f"scatter.glb without EXT_mesh_gpu_instancing support draws {drawn} mesh objects "
          f"(one per species: the plain-node fallback)")
    if 'dropped' in wind:
        print(f"_WIND: {pack}: in every level of every file (read by Blender's glTF reader); "
              "Blender's importer drops custom attributes, so the imported meshes have none")
    elif 'imported' in wind:
        print(f"_WIND: {pack}: imported onto every mesh, values in [0, 1]")


def main():
    packs = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    if not packs:
        print("usage: blender -b --factory-startup --python blender_pack_check.py -- PACK_DIR...", file=sys.stderr)
        sys.exit(2)
    for pack in packs:
        check_pack(pack)
    for message in failures:
        print("FAIL " + message, file=sys.stderr)
    sys.exit(1 if failures else 0)


main()
