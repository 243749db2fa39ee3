#!/usr/bin/env python3
"""Tests of scripts/tree_shape.py on meshes with known answers (standard library only).

Run: python3 tests/tree_shape_test.py
"""
import importlib.util
import json
import itertools
import math
import os
import random
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "scripts" / "tree_shape.py"
MORPHOGEN = ROOT / "build" / "morphogen"

spec = importlib.util.spec_from_file_location("tree_shape", SCRIPT)
tree_shape = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tree_shape)

# the six faces of a box, outward, as corners idx = i + 2 j + 4 k for (x_i, y_j, z_k)
BOX_QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3)]


class Mesh:
    def __init__(self):
        self.vertices = []
        self.faces = []  # 0-based polygons

    def add_box(self, x0, x1, y0, y1, z0, z1):
        base = len(self.vertices)
        for k in (z0, z1):
            for j in (y0, y1):
                for i in (x0, x1):
                    self.vertices.append((i, j, k))
        self.faces += [tuple(base + c for c in quad) for quad in BOX_QUADS]
        return self

    def triangulated(self):
        out = Mesh()
        out.vertices = list(self.vertices)
        out.faces = [(f[0], f[k], f[k + 1]) for f in self.faces for k in range(1, len(f) - 1)]
        return out

    def obj_text(self, negative=False, corner="{}"):
        lines = ["# test mesh"]
        # with negative indices each face is written right after its own vertices
        if negative:
            for face in self.faces:
                for i in face:
                    lines.append("v %r %r %r" % self.vertices[i])
                n = len(face)
                lines.append("f " + " ".join(corner.format(-(n - k)) for k in range(n)))
            return "\n".join(lines) + "\n"
        lines += ["v %r %r %r" % v for v in self.vertices]
        lines += ["f " + " ".join(corner.format(i + 1) for i in face) for face in self.faces]
        return "\n".join(lines) + "\n"


def box(x0, x1, y0, y1, z0, z1):
    return Mesh().add_box(x0, x1, y0, y1, z0, z1).triangulated()


def t_shape():
    """A thin tall box (0.2 x 0.2 x 3) under a wide flat one (4 x 4 x 1), touching at z = 3."""
    return Mesh().add_box(-0.1, 0.1, -0.1, 0.1, 0, 3).add_box(-2, 2, -2, 2, 3, 4).triangulated()


def three_prongs():
    """A thin trunk (z 0..5) under a plate (z 5..5.5) carrying three separate boxes (z 5.5..10).

    H = 10, so the upper half is z in [5, 10): the sections through the plate cut 1 loop, those
    through the prongs 3, and the trunk lies wholly in the lower half. Expected max loops: 3."""
    m = Mesh().add_box(-0.1, 0.1, -0.1, 0.1, 0, 5).add_box(-3, 3, -0.5, 0.5, 5, 5.5)
    for x0 in (-3, -0.5, 2):
        m.add_box(x0, x0 + 1, -0.5, 0.5, 5.5, 10)
    return m.triangulated()


def octahedron():
    m = Mesh()
    m.vertices = [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    for k in range(4):
        a, b = k, (k + 1) % 4
        m.faces += [(a, b, 4), (b, a, 5)]
    return m


def tetrahedron():
    """Vertex (0, 2, 1) lies exactly on the plane z = 1 (the middle of three sections)."""
    m = Mesh()
    m.vertices = [(0, 0, 0), (2, 0, 0), (0, 2, 1), (0, 0, 2)]
    m.faces = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    return m


def hexagonal_prism():
    """Two hexagon caps as single 6-gons (fan-triangulated), six quad sides; circumradius 1."""
    m = Mesh()
    ring = [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3)) for k in range(6)]
    m.vertices = [(x, y, 0.0) for x, y in ring] + [(x, y, 2.0) for x, y in ring]
    m.faces = [tuple(reversed(range(6))), tuple(range(6, 12))]
    m.faces += [(k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k) for k in range(6)]
    return m


def sections(mesh):
    return tree_shape.Sections(mesh.vertices, [tuple(f) for f in mesh.faces])


class TempDirTest(unittest.TestCase):
    def setUp(self):
        self._dir = tempfile.TemporaryDirectory()
        self.dir = Path(self._dir.name)

    def tearDown(self):
        self._dir.cleanup()

    def write(self, name, text):
        path = self.dir / name
        path.write_text(text)
        return path

    def write_mesh(self, name, mesh, **kwargs):
        return self.write(name, mesh.obj_text(**kwargs))

    def run_script(self, *args, morphogen="/nonexistent/morphogen"):
        """Runs the script; morphogen=None leaves --morphogen at its default."""
        option = [] if morphogen is None else ["--morphogen", str(morphogen)]
        done = subprocess.run([sys.executable, str(SCRIPT), *option, *map(str, args)],
                              capture_output=True, text=True, timeout=120)
        self.assertEqual(done.returncode, 0, done.stderr)
        return done

    def json_records(self, *args, **kwargs):
        done = self.run_script("--json", *args, **kwargs)
        return [json.loads(line) for line in done.stdout.splitlines()], done.stderr

    def fake_morphogen(self, body):
        path = self.write("fake_morphogen", "#!/bin/sh\n" + body + "\n")
        path.chmod(0o755)
        return path


class DiameterTest(unittest.TestCase):
    def test_rotating_calipers_match_brute_force(self):
        rng = random.Random(7)
        for trial in range(600):
            n = rng.randint(1, 25)
            if trial % 3 == 0:
                pts = [(rng.random(), rng.random()) for _ in range(n)]
            elif trial % 3 == 1:  # many collinear points and parallel hull edges
                pts = [(rng.randint(0, 3), rng.randint(0, 3)) for _ in range(n)]
            else:
                pts = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n)]
            brute = max((math.dist(a, b) for a, b in itertools.combinations(pts, 2)), default=0.0)
            self.assertAlmostEqual(tree_shape.diameter(pts), brute, places=12, msg=pts)


class SectionTest(unittest.TestCase):
    def test_box_one_loop_everywhere(self):
        s = sections(box(0, 2, 0, 1, 0, 3))
        for h in (0.01, 0.5, 1.5, 2.99):
            width, loops = s.section(h)
            self.assertEqual(loops, 1)
            self.assertAlmostEqual(width, math.sqrt(5))

    def test_octahedron_plane_through_four_vertices(self):
        width, loops = sections(octahedron()).section(0.0)
        self.assertEqual(loops, 1)
        self.assertAlmostEqual(width, 2.0)

    def test_tetrahedron_plane_through_one_vertex(self):
        width, loops = sections(tetrahedron()).section(1.0)
        self.assertEqual(loops, 1)
        self.assertAlmostEqual(width, math.sqrt(5))  # section: triangle (0,2) (0,0) (1,0)

    def test_three_prongs_sections(self):
        s = sections(three_prongs())
        self.assertEqual(s.section(2.0)[1], 1)  # trunk
        self.assertEqual(s.section(5.25)[1], 1)  # plate
        self.assertEqual(s.section(8.0)[1], 3)  # prongs


class ScriptTest(TempDirTest):
    def test_box(self):
        path = self.write_mesh("box.obj", box(0, 2, 0, 1, 0, 3))
        (r,), _ = self.json_records(path)
        self.assertEqual(r["trunk_ratio"], 1.0)
        self.assertEqual(r["max_loops_upper_half"], 1)
        self.assertAlmostEqual(r["width_lowest_quarter"], math.sqrt(5))
        self.assertIsNone(r["self_intersecting"])
        self.assertEqual(r["is_tree"], "n/a")

    def test_t_shape(self):
        path = self.write_mesh("t.obj", t_shape())
        (r,), _ = self.json_records(path)
        self.assertAlmostEqual(r["trunk_ratio"], 0.2 / 4)  # diagonals 0.2 sqrt 2 / 4 sqrt 2
        self.assertLess(r["trunk_ratio"], 0.25)
        self.assertEqual(r["max_loops_upper_half"], 1)

    def test_three_prongs(self):
        path = self.write_mesh("prongs.obj", three_prongs())
        (r,), _ = self.json_records(path)
        self.assertEqual(r["max_loops_upper_half"], 3)
        self.assertAlmostEqual(r["width_upper_half"], math.sqrt(37))
        self.assertAlmostEqual(r["trunk_ratio"], 0.2 * math.sqrt(2) / math.sqrt(37))

    def test_octahedron_vertex_at_section_height(self):
        # 5 sections over z in (-1, 1): h = -0.8 -0.4 0 0.4 0.8; the plane z = 0 holds four vertices
        path = self.write_mesh("octa.obj", octahedron())
        (r,), _ = self.json_records("--sections", 5, path)
        self.assertEqual(r["max_loops_upper_half"], 1)
        self.assertAlmostEqual(r["width_lowest_quarter"], 0.4)
        self.assertAlmostEqual(r["width_upper_half"], 2.0)
        self.assertAlmostEqual(r["trunk_ratio"], 0.2)

    def test_tetrahedron_vertex_at_section_height(self):
        path = self.write_mesh("tetra.obj", tetrahedron())
        (r,), _ = self.json_records("--sections", 3, path)  # h = 1/3, 1, 5/3
        self.assertEqual(r["max_loops_upper_half"], 1)
        self.assertAlmostEqual(r["width_upper_half"], math.sqrt(5))

    def test_quads_negative_indices_and_corner_forms(self):
        quads = Mesh().add_box(0, 2, 0, 1, 0, 3)
        expected, _ = self.json_records(self.write_mesh("tri.obj", quads.triangulated()))
        for corner in ("{}", "{}/1", "{}/1/1", "{}//1"):
            path = self.write_mesh("quads.obj", quads, negative=True, corner=corner)
            vertices, triangles = tree_shape.read_obj(path)
            self.assertEqual((len(vertices), len(triangles)), (24, 12))
            got, _ = self.json_records(path)
            for key in ("trunk_ratio", "max_loops_upper_half", "width_lowest_quarter", "width_upper_half"):
                self.assertAlmostEqual(got[0][key], expected[0][key], msg=(corner, key))
        self.assertEqual(got[0]["max_loops_upper_half"], 1)  # split vertices were merged

    def test_polygon_fan(self):
        path = self.write_mesh("hex.obj", hexagonal_prism())
        self.assertEqual(len(tree_shape.read_obj(path)[1]), 2 * 4 + 6 * 2)
        (r,), _ = self.json_records(path)
        self.assertEqual(r["max_loops_upper_half"], 1)
        self.assertAlmostEqual(r["width_upper_half"], 2.0)
        self.assertAlmostEqual(r["trunk_ratio"], 1.0)

    def test_one_section_has_no_trunk_ratio(self):
        path = self.write_mesh("box.obj", box(0, 1, 0, 1, 0, 1))
        (r,), _ = self.json_records("--sections", 1, path)
        self.assertIsNone(r["trunk_ratio"])
        self.assertEqual(r["max_loops_upper_half"], 1)


class CsvAndSelfIntersectionTest(TempDirTest):
    def test_missing_morphogen_is_na_said_once(self):
        a = self.write_mesh("a.obj", three_prongs())
        b = self.write_mesh("b.obj", box(0, 1, 0, 1, 0, 1))
        done = self.run_script(a, b, morphogen="/nonexistent")
        lines = done.stdout.splitlines()
        self.assertEqual(lines[0], "mesh,vertices,height,footprint_ground,footprint_half_height,footprint_canopy,"
                                   "footprint_all,self_intersecting,trunk_ratio,max_loops_upper_half,is_tree")
        self.assertEqual(lines[1].split(",")[7:], ["n/a", "0.046", "3", "n/a"])
        self.assertEqual(lines[2].split(",")[7:], ["n/a", "1.000", "1", "n/a"])
        self.assertEqual(done.stderr.count("/nonexistent"), 1, done.stderr)

    def test_profile_column_stays_before_new_ones(self):
        path = self.write_mesh("box.obj", box(0, 2, 0, 1, 0, 3))
        done = self.run_script("--profile", path)
        header, row = done.stdout.splitlines()  # footprints are of vertices: only z = 0 and z = 3 have any
        self.assertTrue(header.endswith(",footprint_all,profile,self_intersecting,trunk_ratio,"
                                        "max_loops_upper_half,is_tree"))
        self.assertEqual(row.split(",")[:8], [str(path), "8", "3.000", "2.0", "0.0", "0.0", "2.0", "2 0 0 2"])

    def test_is_tree_from_a_fake_morphogen(self):
        prongs = self.write_mesh("prongs.obj", three_prongs())
        t = self.write_mesh("t.obj", t_shape())
        clean = self.fake_morphogen("""echo '{"faces": 12, "self_intersecting": false}'""")
        records, _ = self.json_records(prongs, t, morphogen=clean)
        self.assertEqual([(r["self_intersecting"], r["is_tree"]) for r in records], [(False, "yes"), (False, "no")])
        dirty = self.fake_morphogen("""echo '{"self_intersecting": true}'""")
        (r,), _ = self.json_records(prongs, morphogen=dirty)
        self.assertEqual((r["self_intersecting"], r["is_tree"]), (True, "no"))
        broken = self.fake_morphogen("echo 'cannot read mesh' >&2; exit 1")
        (r,), err = self.json_records(prongs, morphogen=broken)
        self.assertEqual((r["self_intersecting"], r["is_tree"], r["max_loops_upper_half"]), (None, "n/a", 3))
        self.assertIn("cannot read mesh", err)

    @unittest.skipUnless(os.access(MORPHOGEN, os.X_OK), f"{MORPHOGEN} is not built")
    def test_real_morphogen_box_is_clean(self):
        path = self.write_mesh("box.obj", box(0, 2, 0, 1, 0, 3))
        (r,), _ = self.json_records(path, morphogen=MORPHOGEN)
        self.assertIs(r["self_intersecting"], False)
        self.assertEqual(r["is_tree"], "no")  # one loop: a box is no tree
        done = self.run_script(path, morphogen=None)  # default --morphogen: build/morphogen in the repository
        self.assertEqual(done.stdout.splitlines()[1].split(",")[7], "false")


    @unittest.skipUnless(os.access(MORPHOGEN, os.X_OK), f"{MORPHOGEN} is not built")
    def test_the_executables_tree_measures_agree_on_grown_meshes(self):
        # fitness/architecture/tree_sections.cpp (as the fitness types trunk_ratio and
        # upper_loops) and this script, on random genomes grown by morphogen.
        configs = {}
        for measure in ("trunk_ratio", "upper_loops"):
            configs[measure] = self.write(f"{measure}.json", json.dumps({"fitness": {"type": measure}}))
        for genome in (1, 2, 5, 9):
            path = self.dir / f"grown-{genome}.obj"
            subprocess.run([str(MORPHOGEN), "grow", "--random", str(genome), "-o", str(path)],
                           check=True, capture_output=True)
            (r,), _ = self.json_records(path, morphogen=None)
            scored = {}
            for measure, config in configs.items():
                done = subprocess.run([str(MORPHOGEN), "score", "--mesh", str(path), "--config", str(config), "--json"],
                                      check=True, capture_output=True, text=True)
                scored[measure] = json.loads(done.stdout)["fitness"]
            with self.subTest(genome=genome):
                self.assertEqual(scored["upper_loops"], r["max_loops_upper_half"])
                self.assertAlmostEqual(scored["trunk_ratio"], r["trunk_ratio"], places=12)


if __name__ == "__main__":
    unittest.main()
