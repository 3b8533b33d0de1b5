/// \file
/// Golden-image tests: each case renders one picture with the real headless executable
/// (meshedit-render, OSMesa) and compares it with tests/golden/NAME.png.
///
/// MESHEDIT_UPDATE_GOLDEN=1 in the environment rewrites the references instead (and passes);
/// look at every rewritten PNG before committing it. docs/rendering.md shows them all.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run.h"
#include "support/demo_meshes.h"
#include "support/image_compare.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;

// Small enough to keep every PNG far under 100 KB, large enough to see facets and arrows.
const char* const kSize = "384x288";
// The scans: at 384x288 their triangles are a few pixels and the wires fade out.
const char* const kScanSize = "576x432";

/// One golden image: what to render and how.
struct GoldenCase {
    std::string name;   ///< file stem in tests/golden/ and the gtest parameter name
    std::string input;  ///< relative to the repository root, "demo:STEM" or "assimp:PATH"
    std::vector<std::string> args;  ///< after `FILE -o OUT --size WxH`; tests/golden/data/… paths
                                    ///< are made absolute
    std::string size = kSize;
};

// A polygon-mesh case: `ops` on the quad ball, the result selected.
GoldenCase poly(const std::string& name, const std::string& ops) {
    return {"poly_" + name,
            "dae/quadball.dae",
            {"--ops", ops, "--select", "result", "--flat", "--wireframe"}};
}

// The table. Names group by subject (prefix) so the gallery and a --gtest_filter read well.
const std::vector<GoldenCase>& golden_cases() {
    static const std::vector<GoldenCase> cases = {
        // Flat vs smooth normals: smooth must hide the facets flat shows.
        {"teapot_flat", "dae/teapot.dae", {"--shading", "phong", "--flat"}},
        {"teapot_smooth", "dae/teapot.dae", {"--shading", "phong", "--smooth"}},
        // Local operations on the cube (docs/samples.md reference ops), result selected.
        // Flat normals: smooth ones on a cube make one blurry highlight and hide the edit.
        // Each camera faces the edited edge: flip on −x (az −110), split on the −y/−z edge
        // (from below), collapse on the +x/−z edge (az 120, at distance 7: the default framing
        // of the collapsed cube is tighter than the input's and grazes the border).
        {"cube_input", "dae/cube.dae", {"--flat", "--wireframe", "--camera", "-110,25"}},
        {"cube_flip",
         "dae/cube.dae",
         {"--ops", "flip:0-6", "--select", "e:2-4", "--flat", "--wireframe", "--camera",
          "-110,25"}},
        {"cube_split",
         "dae/cube.dae",
         {"--ops", "split:0-1", "--select", "v8", "--flat", "--wireframe", "--camera", "-150,-35"}},
        {"cube_split_edge",
         "dae/cube.dae",
         {"--ops", "split:0-1", "--select", "0-8", "--flat", "--wireframe", "--camera",
          "-150,-35"}},
        {"cube_collapse",
         "dae/cube.dae",
         {"--ops", "collapse:1-3", "--select", "v:1", "--flat", "--wireframe", "--camera",
          "120,30,7"}},
        // Loop subdivision: levels, a genus-1 surface, creases, a boundary. The torus is flat
        // shaded without wires: at 9,216 faces 1 px wires would turn it black.
        {"cube_loop1", "dae/cube.dae", {"--ops", "loop:1", "--wireframe"}},
        {"cube_loop2", "dae/cube.dae", {"--ops", "loop:2", "--wireframe"}},
        {"cube_loop3", "dae/cube.dae", {"--ops", "loop:3", "--wireframe"}},
        // Loop step by step (docs/teaching.md), flat: after phase 1 the new positions (teal)
        // and the edge points (purple), on the inside of the bowl, where smoothing lifts
        // them off the surface toward the eye (on a convex shape they sink inside it);
        // after phase 2 the new vertices and the edges across the old faces (purple); after
        // phase 3 the flipped edges (yellow). Phase 4 is cube_loop1.
        {"bowl_loop_phase1",
         "dae/bowl.dae",
         {"--ops", "loop_step", "--flat", "--wireframe", "--camera", "30,35"}},
        {"cube_loop_phase1", "dae/cube.dae", {"--ops", "loop_step", "--flat", "--wireframe"}},
        {"cube_loop_phase2", "dae/cube.dae", {"--ops", "loop_step:2", "--flat", "--wireframe"}},
        {"cube_loop_phase3", "dae/cube.dae", {"--ops", "loop_step:3", "--flat", "--wireframe"}},
        // Stencils (docs/teaching.md) of the cube's vertex 7 (valence 6, facing the camera):
        // interior; on a hole's rim; on two creases (Loop's own weights: the crease rule is
        // the same).
        {"stencil_interior",
         "dae/cube.dae",
         {"--select", "v:7", "--stencil", "loop", "--flat", "--wireframe"},
         "576x432"},
        {"stencil_boundary",
         "dae/cube.dae",
         {"--ops", "make_boundary:f7", "--select", "v:7", "--stencil", "loop", "--flat",
          "--wireframe"},
         "576x432"},
        {"stencil_crease",
         "dae/cube.dae",
         {"--ops", "crease:7-6,crease:7-3", "--select", "v:7", "--stencil", "loop-original",
          "--flat", "--wireframe"},
         "576x432"},
        {"stencil_cc_edge",
         "dae/quadcube.dae",
         {"--select", "e:0-1", "--stencil", "catmull-clark", "--flat", "--wireframe"},
         "576x432"},
        // Rewiring diagrams (docs/teaching.md) of the cube's edge 7-4: the names of the
        // diagrams above flip(), split() and collapse(), what changed coloured and listed.
        {"diagram_flip", "dae/cube.dae", {"--ops", "flip:7-4", "--op-diagram"}, "960x640"},
        {"diagram_split", "dae/cube.dae", {"--ops", "split:7-4", "--op-diagram"}, "1024x880"},
        {"diagram_collapse", "dae/cube.dae", {"--ops", "collapse:7-4", "--op-diagram"}, "1024x880"},
        // Scalar fields with their legends (docs/fields.md), on the teapot; distance from
        // the spout's tip.
        {"field_gauss", "dae/teapot.dae", {"--field", "gauss"}, "480x360"},
        {"field_mean", "dae/teapot.dae", {"--field", "mean"}, "480x360"},
        {"field_valence", "dae/teapot.dae", {"--field", "valence", "--wireframe"}, "480x360"},
        {"field_aspect", "dae/teapot.dae", {"--field", "aspect", "--flat"}, "480x360"},
        {"field_min_angle",
         "dae/teapot.dae",
         {"--field", "min_angle", "--flat", "--colormap", "magma"},
         "480x360"},
        {"field_dihedral", "dae/teapot.dae", {"--field", "dihedral"}, "480x360"},
        {"field_edge_length", "dae/teapot.dae", {"--field", "edge_length"}, "480x360"},
        {"field_face_area", "dae/teapot.dae", {"--field", "face_area", "--flat"}, "480x360"},
        {"field_distance",
         "dae/teapot.dae",
         {"--field", "distance", "--field-source", "v0"},
         "480x360"},
        // Mode 7: the mirror teapot in the default (procedural) environment, and in a
        // checkerboard made by the test (the seam at θ = ±π shows as a line if the mip level
        // jumps there).
        {"envmap_teapot", "dae/teapot.dae", {"--shading", "envmap"}, "480x360"},
        {"envmap_checker",
         "dae/teapot.dae",
         {"--shading", "7", "--envmap", "tests/golden/data/checker_env.png"},
         "480x360"},
        // Modes 8 and 9 with the starter shaders (shaders/user): toon bands, stripes at time 0.
        {"user8_teapot",
         "dae/teapot.dae",
         {"--shading", "8", "--shader-dir", "shaders/user"},
         "480x360"},
        {"user9_teapot",
         "dae/teapot.dae",
         {"--shading", "9", "--shader-dir", "shaders/user"},
         "480x360"},
        // Auto Smooth at 30°: the teapot stays smooth but its lid's and spout's rims, where
        // faces turn by more than 30°, are lit crisply.
        {"auto_smooth_teapot", "dae/teapot.dae", {"--auto-smooth", "30"}, "480x360"},
        {"torus_loop2", "dae/torus.dae", {"--ops", "loop:2", "--flat", "--camera", "30,40"}},
        {"creased_input", "dae/creased.dae", {"--wireframe"}},
        {"creased_loop3", "dae/creased.dae", {"--ops", "loop:3"}},
        {"bowl_loop2", "dae/bowl.dae", {"--ops", "loop:2", "--camera", "30,35"}},
        // Catmull-Clark and linear subdivision of polygons (docs/subdivision.md): the quad
        // cube's levels; linear keeps the cube; creases on the quad cube's top square and one
        // vertical edge (vertex 3 = (+,+,+) a corner, 2 below it a dart); the creased
        // cylinder; the quad ball.
        {"cc_cube_input", "dae/quadcube.dae", {"--flat", "--wireframe"}},
        {"cc_cube1", "dae/quadcube.dae", {"--ops", "catmull_clark:1", "--wireframe"}},
        {"cc_cube2", "dae/quadcube.dae", {"--ops", "catmull_clark:2", "--wireframe"}},
        {"cc_cube3", "dae/quadcube.dae", {"--ops", "catmull_clark:3", "--wireframe"}},
        {"linear_cube2", "dae/quadcube.dae", {"--ops", "linear:2", "--flat", "--wireframe"}},
        {"cc_creased_cube",
         "dae/quadcube.dae",
         {"--ops", "crease:6-7,crease:7-3,crease:3-1,crease:1-6,crease:3-2,catmull_clark:3",
          "--wireframe"}},
        {"cc_creased", "dae/creased.dae", {"--ops", "catmull_clark:2", "--wireframe"}},
        {"cc_quadball", "dae/quadball.dae", {"--ops", "catmull_clark:2", "--wireframe"}},
        // What a mesh carries (docs/attributes.md): assimp's textured duck (COLLADA, a TGA
        // texture) as read, after Loop and Catmull-Clark (face-varying UVs, seams kept) and
        // in the UV checker; a vertex-coloured model; the material colours of one model.
        {"textured_duck", "assimp:Collada/duck.dae", {"--camera", "60,15"}},
        // 3ds Max's earth: numbers with decimal commas and a texture named from the drive's
        // root in another case ("\..\LWO\...\EarthCylindric.jpg"), both found as meant.
        {"textured_earth", "assimp:Collada/earthCylindrical.DAE", {}},
        {"textured_duck_loop1",
         "assimp:Collada/duck.dae",
         {"--ops", "triangulate,loop:1", "--camera", "60,15"}},
        {"textured_duck_cc1",
         "assimp:Collada/duck.dae",
         {"--ops", "catmull_clark:1", "--camera", "60,15"}},
        {"textured_duck_simplify10",
         "assimp:Collada/duck.dae",
         {"--ops", "triangulate,simplify:0.1", "--camera", "60,15"}},
        // Remeshed (docs/remesh.md): the seams stay as features and every corner is taken
        // from the input on its own side of them, so the checker's charts come through.
        {"textured_duck_remesh_checker",
         "assimp:Collada/duck.dae",
         {"--ops", "triangulate,remesh", "--color", "checker", "--camera", "60,15"}},
        // The checker shows the charts: eye, beak and wings each their own, head and body
        // squeezed into one cell of the yellow (seams orange).
        {"textured_duck_checker",
         "assimp:Collada/duck.dae",
         {"--color", "checker", "--camera", "60,15"}},
        // glTF's textured box: its PNG embedded in the .glb, decoded from the bytes.
        {"textured_box_glb",
         "assimp:glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
         {"--camera", "30,25"}},
        // A material whose texture reads the second texture coordinate set (glTF's
        // baseColorTexture.texCoord 1): the whole 8 × 8 checker; the first set would squeeze
        // the square into one black cell.
        {"textured_second_set", "tests/golden/data/second_uv_set_square.gltf", {}},
        {"vertex_colours", "assimp:Collada/kwxport_test_vcolors.dae", {"--color", "vertex"}},
        // QEM simplification (docs/simplify.md): the teapot (4,032 triangles) at 10% and 2.5%;
        // rims, spout tip and handle keep their shape, flat regions get the big triangles.
        {"teapot_input_wire", "dae/teapot.dae", {"--flat", "--wireframe"}},
        // The scanned bunny (75,408 triangles, CGAL's demo data) at 10%: the detail stays
        // where the curvature is (ears, face, feet).
        {"bunny_simplify10",
         "demo:bunny00",
         {"--ops", "simplify:0.1", "--flat", "--wireframe"},
         kScanSize},
        {"teapot_simplify10", "dae/teapot.dae", {"--ops", "simplify:0.1", "--flat", "--wireframe"}},
        {"teapot_simplify2",
         "dae/teapot.dae",
         {"--ops", "simplify:0.025", "--flat", "--wireframe"}},
        // Isotropic remeshing (docs/remesh.md): the patch tessellation's uneven triangles (dense
        // at the spout and the lid's knob) become even ones of the mean length, then of 0.15.
        {"teapot_remesh", "dae/teapot.dae", {"--ops", "remesh", "--flat", "--wireframe"}},
        {"teapot_remesh_015", "dae/teapot.dae", {"--ops", "remesh:0.15", "--flat", "--wireframe"}},
        // The bunny remeshed at edge length 0.03 (5,814 triangles, so about 3.6 times its mean
        // length): near-equilateral triangles of one size everywhere.
        {"bunny_remesh_003",
         "demo:bunny00",
         {"--ops", "remesh:0.03", "--flat", "--wireframe"},
         kScanSize},
        // Smoothing (docs/smoothing.md): the scanned bunny as read, after 50 uniform Laplacian
        // steps (λ 0.5: the ears thin and the whole shrinks) and after 50 Taubin λ|μ steps
        // (the scanner's ridges go, the shape and its size stay).
        {"bunny_input", "demo:bunny00", {"--flat"}, kScanSize},
        {"bunny_smooth50", "demo:bunny00", {"--ops", "smooth:50,0.5", "--flat"}, kScanSize},
        {"bunny_taubin50", "demo:bunny00", {"--ops", "taubin:50,0.5,-0.53", "--flat"}, kScanSize},
        // CGAL's fandisk (an OFF file: no crease marks) remeshed with a feature angle of 40°:
        // its 710 sharp edges are marked as creases first (drawn green) and stay sharp and
        // straight; without it remeshing rounds and jags them (docs/remesh.md).
        {"fandisk_remesh_feature40",
         "demo:fandisk",
         {"--ops", "remesh:0.04,3,40", "--flat", "--wireframe"}},
        // Loop's first phase on the teapot with its marks only within two rings of vertex
        // 600 (Alt+N, --marks-near): everywhere they blur the whole teapot.
        {"teapot_loop1_near",
         "dae/teapot.dae",
         {"--ops", "loop_step", "--select", "v:600", "--marks-near"}},
        // A teapot body patch evaluated at (0.4, 0.6) by de Casteljau (--patch-steps): the
        // three levels along u on every row, then the curve in v and its levels down to the
        // point S(u, v) (red).
        {"patch_steps_u", "bez/teapot.bez", {"--patch-steps", "4,0.4,0.6,3"}},
        {"patch_steps_uv", "bez/teapot.bez", {"--patch-steps", "4,0.4,0.6,6"}},
        // Catmull-Clark as it is taught (cc_steps.h, Alt+Shift+C), phase by phase on the
        // quad cube: face points (each face poked), edge points (old edges split, the new
        // vertices moved to their edge points), vertex points (the corners pulled in), and
        // the reconnect that leaves 24 quads, the same as one `catmull_clark`.
        {"cc_phase1", "dae/quadcube.dae", {"--ops", "cc_step", "--flat", "--wireframe"}},
        {"cc_phase2", "dae/quadcube.dae", {"--ops", "cc_step:2", "--flat", "--wireframe"}},
        {"cc_phase3", "dae/quadcube.dae", {"--ops", "cc_step:3", "--flat", "--wireframe"}},
        {"cc_phase4", "dae/quadcube.dae", {"--ops", "cc_step:4", "--flat", "--wireframe"}},
        // CGAL's mech-holes-shark with its 4 holes (red borders), and filled as Liepa fills
        // them: minimum-weight triangles refined to the surrounding edge length and faired, so
        // each patch continues the surface (docs/cli.md, repair --fair).
        {"shark_holes", "demo:mech-holes-shark", {"--flat", "--wireframe"}},
        {"shark_fill_fair",
         "demo:mech-holes-shark",
         {"--ops", "fill_holes_fair", "--flat", "--wireframe"}},
        // One hole filled by an edge of its border (fill_fair:1-1372, Ctrl+Shift+F): the
        // 48-edge hole along the top; the other three stay open (red).
        {"shark_fill_one_fair",
         "demo:mech-holes-shark",
         {"--ops", "fill_fair:1-1372", "--flat", "--wireframe"}},
        // assimp's 2CylinderEngine, whose exporter tessellated each surface patch apart:
        // merged by distance, the cracks between patches stay open (red borders all over the
        // fins, 894 loops); repaired, the T-junction stitch closes most of them (393 loops,
        // the rest farther apart than the tolerances; docs/repair.md).
        {"engine_merged",
         "assimp:glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
         {"--ops", "merge_by_distance,remove_degenerate"}},
        {"engine_stitched",
         "assimp:glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
         {"--ops", "repair"}},
        // The Problems panel's marks (--problems), each kind in its colour through the
        // surface: CGAL's cube-shuffled, whose disagreeing faces the loader cut apart
        // (magenta dots where it cut), leaving holes (yellow loops) and small parts (brown);
        // degtri_sliding's four zero-area triangles along one line (cyan dots and sides) and
        // its hole; beam, a closed box whose faces all point inward (blue edges).
        // Selections as the session records them and `--select sel` draws them: what a box
        // over the middle of a 5 x 5 grid selects (its session step), and the edge loop
        // around the quad ball's equator (Alt+click), on round across valence-4 vertices.
        {"region_box_selected",
         "tests/golden/data/grid5.obj",
         {"--ops", "select:f6..8+f11..13+f16..18", "--select", "sel", "--flat", "--wireframe",
          "--up", "z", "--camera", "30,45"}},
        {"region_loop_selected",
         "dae/quadball.dae",
         {"--ops", "select_loop:7-12", "--select", "sel", "--flat", "--wireframe", "--camera",
          "35,10"}},
        // A plateau modelled as in Blender: the middle 3 x 3 quads of a 5 x 5 grid extruded as
        // one region by 0.6, then inset as one region by 0.3 (Alt+I): a ring of 12 quads, 0.3
        // wide all round (even at the corners), on top of the walls.
        {"region_inset",
         "tests/golden/data/grid5.obj",
         {"--ops",
          "extrude_region:f6..8+f11..13+f16..18:0.6,inset_region:f6..8+f11..13+f16..18:0.3",
          "--flat", "--wireframe", "--up", "z", "--camera", "30,45"}},
        // Subdividing a selection with a smooth scheme (Ctrl+Shift+W, Alt+Shift+W): Loop inside
        // a patch of the twice-subdivided icosahedron (face 0 grown twice), Catmull-Clark
        // inside the quad ball's 3 x 3 patch around face 75; the border stays and the faces
        // beside it are cut into fans (the transition ring).
        {"region_loop_cap",
         "dae/icosahedron.dae",
         {"--ops", "loop:2,select:f0,select_more,select_more,loop_region:sel", "--flat",
          "--wireframe", "--camera", "-35,35"}},
        {"region_catmull_clark",
         "dae/quadball.dae",
         {"--ops", "select:f75,select_more,catmull_clark_region:sel", "--flat", "--wireframe",
          "--camera", "35,10"}},
        {"problems_cut_cube", "demo:cube-shuffled", {"--problems", "--flat", "--wireframe"}},
        {"problems_degenerate", "demo:degtri_sliding", {"--problems", "--flat", "--wireframe"}},
        {"problems_inside_out", "demo:beam", {"--problems", "--flat", "--wireframe"}},
        // One selection of each element type. Vertex 0 = (−0.53, 0.85, 0) and 1 = (0.53, 0.85,
        // 0) share the faces (0,5,1) on +z and (0,1,7) on −z: each camera looks straight at
        // its element (az = atan2(x, z), el = asin(y)), so nothing sits on the silhouette.
        {"select_vertex",
         "dae/icosahedron.dae",
         {"--select", "v:0", "--wireframe", "--camera", "-90,58"}},
        {"select_edge",
         "dae/icosahedron.dae",
         {"--select", "e:0-1", "--wireframe", "--camera", "0,70"}},
        {"select_halfedge",
         "dae/icosahedron.dae",
         {"--select", "h:0-1", "--wireframe", "--camera", "0,70"}},
        {"select_halfedge_twin",
         "dae/icosahedron.dae",
         {"--select", "h:1-0", "--wireframe", "--camera", "0,70"}},
        // Zoomed out: the arrowhead keeps its size in pixels.
        {"select_halfedge_far",
         "dae/icosahedron.dae",
         {"--select", "h:0-1", "--wireframe", "--camera", "0,70,9"}},
        {"select_face",
         "dae/icosahedron.dae",
         {"--select", "f:0", "--wireframe", "--camera", "-45,35"}},
        // Polygon meshes and their local operations (docs/halfedge.md): the quad ball, face
        // 75 = 85-22-23-88 facing the camera, each result selected (--select result). The
        // wireframe shows polygon edges, not the display's diagonals.
        {"poly_input", "dae/quadball.dae", {"--flat", "--wireframe"}},
        poly("extrude", "extrude:f75:0.4,0.3"),
        poly("extrude_mid_drag", "extrude:f75:0.15,0.1"),
        poly("inset", "inset:f75:0.4"),
        poly("bevel_vertex", "bevel:v85:0.4"),
        poly("bevel_mid_drag", "bevel:v85:0.2"),
        poly("bevel_edge", "bevel:85-88:0.3"),
        poly("poke", "poke:f75"),
        poly("collapse_face", "collapse:f75"),
        poly("collapse_edge", "collapse:85-88"),
        poly("dissolve_edge", "dissolve:85-88"),
        poly("dissolve_vertex", "dissolve:v85"),
        poly("bisect", "bisect:85-88"),
        poly("flip", "flip:85-88"),
        poly("split", "split:85-88"),
        poly("make_boundary", "make_boundary:f75"),
        poly("fill", "make_boundary:f75,fill:85-22"),
        // Weld: a six-sided hole, then its two edges at vertex 22 zipped into one.
        {"poly_weld_before",
         "dae/quadball.dae",
         {"--ops", "make_boundary:f75,make_boundary:f74", "--select", "e:22-23", "--flat",
          "--wireframe"}},
        poly("weld", "make_boundary:f75,make_boundary:f74,weld:85-22+22-23"),
        {"poly_triangulate", "dae/quadball.dae", {"--ops", "triangulate", "--flat", "--wireframe"}},
        // Normals as colour: reversed faces point inward, so each shows the colour of the
        // opposite side of the ball.
        {"poly_flip_orientation",
         "dae/quadball.dae",
         {"--ops", "flip_orientation", "--shading", "0", "--flat", "--wireframe"}},
        // de Casteljau: every level of the degree-5 curve at t = 0.5, then t = 0.25.
        {"curve6_level0", "bez/curve6.bzc", {"--level", "0", "--t", "0.5"}},
        {"curve6_level1", "bez/curve6.bzc", {"--level", "1", "--t", "0.5"}},
        {"curve6_level2", "bez/curve6.bzc", {"--level", "2", "--t", "0.5"}},
        {"curve6_level3", "bez/curve6.bzc", {"--level", "3", "--t", "0.5"}},
        {"curve6_level4", "bez/curve6.bzc", {"--level", "4", "--t", "0.5"}},
        {"curve6_level5", "bez/curve6.bzc", {"--level", "5", "--t", "0.5"}},
        {"curve6_t025", "bez/curve6.bzc", {"--level", "5", "--t", "0.25"}},
        {"curve6_no_curve", "bez/curve6.bzc", {"--level", "5", "--t", "0.25", "--no-curve"}},
        // Bezier patches tessellated, with and without their control nets.
        {"teapot_bez", "bez/teapot.bez", {"--smooth"}},
        {"teapot_bez_net", "bez/teapot.bez", {"--smooth", "--net"}},
        // Back faces are culled only when every part is closed and outward: the inside-out
        // cube on the right must still be drawn (shaded two-sided).
        {"cubes_one_inside_out", "tests/golden/data/cubes_one_inside_out.obj", {"--flat"}},
        // The wireframe overlay toggled on a smooth surface.
        {"torus_wireframe_off", "dae/torus.dae", {"--smooth"}},
        {"torus_wireframe_on", "dae/torus.dae", {"--smooth", "--wireframe"}},
        // Shading modes, each on the same teapot.
        {"shading_0_normals", "dae/teapot.dae", {"--shading", "0", "--smooth"}},
        {"shading_1_phong", "dae/teapot.dae", {"--shading", "1", "--smooth"}},
        {"shading_2_grey", "dae/teapot.dae", {"--shading", "2"}},
        {"shading_3_studio", "dae/teapot.dae", {"--shading", "3", "--smooth"}},
        {"shading_4_matcap", "dae/teapot.dae", {"--shading", "4", "--smooth"}},
        {"shading_5_depth", "dae/teapot.dae", {"--shading", "5", "--smooth"}},
        {"shading_6_hemisphere", "dae/teapot.dae", {"--shading", "6", "--smooth"}},
        // 7–9 alias mode 1 until they get their own look (render/shading.h): no images yet.
    };
    return cases;
}

fs::path source_dir() {
    return MESHEDIT_SOURCE_DIR;
}
fs::path golden_dir() {
    return source_dir() / "tests" / "golden";
}
fs::path out_dir() {
    return fs::path(MESHEDIT_BUILD_DIR) / "golden_out";
}

// MESHEDIT_RENDER_EXE in the environment runs another build (or a stand-in) instead.
std::string render_exe() {
    const char* env = std::getenv("MESHEDIT_RENDER_EXE");
    return env != nullptr && *env != '\0' ? env : MESHEDIT_RENDER_EXE;
}

// MESHEDIT_RENDER_BACKEND (ctest sets it: the suite runs once per backend) goes to
// meshedit-render through the environment; here it only keeps each backend's files apart.
std::string backend_suffix() {
    const char* env = std::getenv("MESHEDIT_RENDER_BACKEND");
    return env != nullptr && *env != '\0' ? std::string(".") + env : std::string();
}

bool update_mode() {
    const char* env = std::getenv("MESHEDIT_UPDATE_GOLDEN");
    return env != nullptr && std::string(env) == "1";
}

std::string command_line(const std::string& exe, const std::vector<std::string>& args) {
    std::string line = exe;
    for (const std::string& a : args) {
        line += " " + a;
    }
    return line;
}

// gtest prints a failing parameter; the name is what identifies it (not its bytes).
void PrintTo(const GoldenCase& c, std::ostream* os) {
    *os << c.name;
}

// A case's input: a file of the repository, or "demo:STEM", a scan of CGAL's demo data set
// (tests/support/demo_meshes.h) unpacked into the build.
fs::path input_path(const std::string& input) {
    if (input.rfind("demo:", 0) == 0) {
        return test::demo_mesh(input.substr(5), fs::path(MESHEDIT_BUILD_DIR) / "demo_data");
    }
    if (input.rfind("assimp:", 0) == 0) {
        // assimp-testmodels' files, installed by scripts/install-deps.sh, read where they are.
        return fs::path("/usr/share/assimp/models") / input.substr(7);
    }
    return source_dir() / input;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesReference) {
    const GoldenCase& c = GetParam();
    const fs::path render_dir = out_dir() / "render";
    fs::create_directories(render_dir);
    const fs::path rendered = render_dir / (c.name + backend_suffix() + ".png");
    fs::remove(rendered);  // a stale file must not pass for a fresh render

    std::vector<std::string> args = {input_path(c.input).string(), "-o", rendered.string(),
                                     "--size", c.size};
    for (const std::string& arg : c.args) {
        // Files of the repository among the options (an --envmap) are relative to its root.
        const bool in_repo = arg.rfind("tests/golden/data/", 0) == 0 || arg == "shaders/user";
        args.push_back(in_repo ? (source_dir() / arg).string() : arg);
    }
    const std::string exe = render_exe();
    const std::string command = command_line(exe, args);
    // llvmpipe on two shared cores needs a few seconds for the Loop-3 meshes; 120 s only
    // catches hangs.
    const RunResult run = run_program(exe, args, 120.0);
    ASSERT_FALSE(run.timed_out) << "render timed out: " << command;
    ASSERT_EQ(run.signal, 0) << "render crashed (signal " << run.signal << "): " << command
                             << "\nstderr:\n"
                             << run.err;
    ASSERT_EQ(run.exit_code, 0) << "render failed: " << command << "\nstderr:\n" << run.err;
    ASSERT_TRUE(fs::exists(rendered))
        << "render exited 0 but wrote no " << rendered << ": " << command;

    const fs::path reference = golden_dir() / (c.name + ".png");
    if (update_mode()) {
        if (same_file_bytes(rendered, reference)) {
            std::cout << "golden: unchanged " << reference.string() << "\n";
            return;
        }
        fs::copy_file(rendered, reference, fs::copy_options::overwrite_existing);
        std::cout << "golden: rewrote " << reference.string() << "\n";
        // ctest hides a passing test's output; the list of rewritten files stays here.
        std::ofstream(out_dir() / "rewritten.txt", std::ios::app) << reference.string() << "\n";
        return;
    }
    ASSERT_TRUE(fs::exists(reference))
        << "no reference image " << reference.string() << "\n  create it with "
        << "`MESHEDIT_UPDATE_GOLDEN=1 make test` (or `MESHEDIT_UPDATE_GOLDEN=1 ctest -L golden` "
        << "in the build folder), then open the PNG and check it shows the right thing before "
        << "committing it";
    EXPECT_TRUE(images_match(rendered, reference, out_dir(), c.name + backend_suffix()))
        << "command: " << command;
}

INSTANTIATE_TEST_SUITE_P(Renders, Golden, ::testing::ValuesIn(golden_cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& param_info) {
                             return param_info.param.name;
                         });

// Every PNG in tests/golden/ belongs to a case, so a renamed or dropped case does not leave
// an unchecked image behind (or in the gallery).
// --envmap refuses what is not an equirectangular image, naming the file, before any GL.
TEST(EnvironmentMap, BadImagesAreRefusedByName) {
    const fs::path dir = out_dir() / "envmap";
    fs::create_directories(dir);
    const std::string mesh = (source_dir() / "dae/cube.dae").string();
    const std::string out = (dir / "x.png").string();
    const auto run = [&](const std::string& env) {
        return run_program(render_exe(), {mesh, "-o", out, "--shading", "7", "--envmap", env},
                           60.0);
    };
    const RunResult not_image = run(mesh);
    EXPECT_EQ(not_image.exit_code, 2);
    EXPECT_NE(not_image.err.find("cube.dae: cannot read the environment image"), std::string::npos)
        << not_image.err;
    // A square image is not equirectangular (2:1).
    const RunResult wrong_shape =
        run((source_dir() / "tests/golden/data/checker_square.png").string());
    EXPECT_EQ(wrong_shape.exit_code, 2);
    EXPECT_NE(wrong_shape.err.find(
                  "not equirectangular: it should be twice as wide as high, it is 64 × 64"),
              std::string::npos)
        << wrong_shape.err;
}

// A user shader that does not compile: exit 1, the error naming the file and its line.
TEST(UserShaders, CompileErrorsNameTheFileAndLine) {
    const fs::path dir = out_dir() / "user_shaders";
    fs::create_directories(dir);
    std::ifstream starter(source_dir() / "shaders/user/mesh8.frag");
    std::stringstream text;
    text << starter.rdbuf();
    std::string broken = text.str();
    const std::size_t at = broken.find("float band = ");
    ASSERT_NE(at, std::string::npos);
    broken.insert(at + std::string("float band = ").size(), "oops");
    const std::size_t line =
        1 + static_cast<std::size_t>(
                std::count(broken.begin(), broken.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    std::ofstream(dir / "mesh8.frag") << broken;
    const RunResult r =
        run_program(render_exe(),
                    {(source_dir() / "dae/cube.dae").string(), "-o", (dir / "x.png").string(),
                     "--shading", "8", "--shader-dir", dir.string()},
                    60.0);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find((dir / "mesh8.frag").string() + " does not compile: line " +
                         std::to_string(line) + ", column"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("oopslight"), std::string::npos) << r.err;
}

TEST(GoldenSet, NoOrphanReferences) {
    std::set<std::string> names;
    for (const GoldenCase& c : golden_cases()) {
        EXPECT_TRUE(names.insert(c.name).second) << "duplicate case name " << c.name;
    }
    if (!fs::exists(golden_dir())) {
        return;  // nothing generated yet; each case reports its missing reference
    }
    for (const auto& entry : fs::directory_iterator(golden_dir())) {
        if (entry.path().extension() == ".png") {
            EXPECT_TRUE(names.count(entry.path().stem().string()) != 0)
                << entry.path().string() << " has no case in golden_test.cpp";
        }
    }
}

// The gallery in docs/rendering.md links every golden image, so the doc cannot fall behind.
TEST(GoldenSet, GalleryListsEveryCase) {
    std::ifstream in(source_dir() / "docs" / "rendering.md");
    ASSERT_TRUE(in) << "docs/rendering.md is missing";
    std::stringstream text;
    text << in.rdbuf();
    for (const GoldenCase& c : golden_cases()) {
        const std::string link = "(../tests/golden/" + c.name + ".png)";
        EXPECT_NE(text.str().find(link), std::string::npos)
            << "docs/rendering.md has no image link " << link;
    }
}

}  // namespace
}  // namespace meshedit::test
