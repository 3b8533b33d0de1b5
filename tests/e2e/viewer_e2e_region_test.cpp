/// \file
/// End-to-end tests of region selection and the operations on a region, in a real window on
/// a 5 x 5 quad grid: a box drag, Shift+X (extrude the region), Shift+W (subdivide it); a
/// lasso and Shift+Delete, an Alt+click edge loop and Delete. Each saved file equals, byte for
/// byte, what `meshedit convert` makes of the input with the session the viewer exported;
/// goldens of the box selection, the loop, the extruded and the subdivided region.

#include <fstream>

#include "meshedit/ops/ops.h"
#include "meshedit/overlay/region_pick.h"
#include "view_pixels.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 700;
constexpr int kN = 5;  // quads a side: vertex (i, j) is j (kN + 1) + i, quad (i, j) is j kN + i
const std::vector<std::uint32_t> kMiddle = {6, 7, 8, 11, 12, 13, 16, 17, 18};  // the middle 3 x 3

void write_grid(const fs::path& path) {
    std::ofstream out(path);
    for (int j = 0; j <= kN; ++j) {
        for (int i = 0; i <= kN; ++i) {
            out << "v " << i << ' ' << j << " 0\n";
        }
    }
    for (int j = 0; j < kN; ++j) {
        for (int i = 0; i < kN; ++i) {
            const int a = j * (kN + 1) + i + 1;
            out << "f " << a << ' ' << a + 1 << ' ' << a + kN + 2 << ' ' << a + kN + 1 << '\n';
        }
    }
}

/// The window rectangle around the centroids of `faces`, `margin` pixels wider each way.
struct Rect {
    int x0, y0, x1, y1;
    bool holds(const Pixel& p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};
Rect around(const View& view, const Mesh& mesh, const std::vector<std::uint32_t>& faces,
            int margin) {
    Rect r{kWidth, kHeight, 0, 0};
    for (const std::uint32_t f : faces) {
        const std::optional<Pixel> p = face_pixel(view, mesh, Face(f));
        EXPECT_TRUE(p) << "face " << f << " is not in the opening view";
        if (p) {
            r = {std::min(r.x0, p->x), std::min(r.y0, p->y), std::max(r.x1, p->x),
                 std::max(r.y1, p->y)};
        }
    }
    return {r.x0 - margin, r.y0 - margin, r.x1 + margin, r.y1 + margin};
}

/// The faces whose centroid the rectangle holds: what a box over it selects on the grid.
std::vector<std::uint32_t> faces_in(const View& view, const Mesh& mesh, const Rect& r) {
    std::vector<std::uint32_t> out;
    for (const Face f : mesh.faces()) {
        const std::optional<Pixel> p = face_pixel(view, mesh, f);
        if (p && r.holds(*p)) {
            out.push_back(f.idx());
        }
    }
    return out;
}

class RegionE2E : public ViewerE2E {
protected:
    /// The grid written twice: the input a session replays from, and the document.
    std::pair<fs::path, fs::path> grid_files() {
        const fs::path original = work_ / "input" / "grid.obj";
        fs::create_directories(original.parent_path());
        write_grid(original);
        const fs::path doc = work_ / "grid.obj";
        fs::copy_file(original, doc);
        return {original, doc};
    }

    /// The viewer on `doc` (the 5 x 5 grid), its window once the title shows the grid.
    std::unique_ptr<BackgroundProcess> open_grid(const fs::path& doc,
                                                 std::optional<ViewerWindow>& window) {
        auto viewer = start_viewer(doc, std::to_string(kWidth) + "x" + std::to_string(kHeight));
        window.emplace(*viewer);
        std::string title;
        if (window->ok()) {
            EXPECT_TRUE(window->wait_title("V 36 E 60 F 25", false, 20s, &title)) << title;
        }
        return viewer;
    }

    /// Moves the pointer off the mesh (no hover highlight) and compares P's screenshot number
    /// `n` with the golden `name`.
    void golden_view(BackgroundProcess& viewer, const ViewerWindow& window, std::size_t n,
                     const std::string& name) {
        window.move_to(kWidth - 15, 15);
        const fs::path shot = screenshot(viewer, window, n);
        ASSERT_FALSE(shot.empty());
        expect_golden(shot, name);
    }

    /// Saves, exports the session, replays it with `meshedit convert` from `original`, and
    /// expects the replay to be the saved file byte for byte.
    void expect_replay_equals_saved(BackgroundProcess& viewer, const ViewerWindow& window,
                                    const fs::path& original, const fs::path& doc) {
        std::string title;
        window.key("ctrl+s");
        ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
        const fs::path session = work_ / (doc.stem().string() + ".ops");
        ASSERT_NO_FATAL_FAILURE(answer_prompt(window, "ctrl+shift+e", std::nullopt));
        ASSERT_TRUE(wait_until([&] { return fs::exists(session); }, 20s)) << viewer.err();
        std::cout << "session:\n" << read_file(session);
        fs::path replayed = work_ / "replayed";
        replayed += doc.extension();
        std::string ops = "@";  // appended: `"@" + string` trips a GCC 12 -Wrestrict false alarm
        ops += session.string();
        const RunResult convert =
            run_meshedit({"convert", original.string(), replayed.string(), "--ops", ops});
        ASSERT_EQ(convert.exit_code, 0) << convert.err;
        EXPECT_TRUE(same_file_bytes(replayed, doc)) << "the replay differs from the saved file";
        window.key("ctrl+q");
        expect_exit(viewer, 0);
    }
};

// B and a drag over the middle 3 x 3, Shift+X with a typed height, Shift+W.
TEST_F(RegionE2E, BoxSelectExtrudeAndSubdivideTheRegion) {
    const auto [original, doc] = grid_files();
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);
    const Rect box = around(view, input, kMiddle, 4);
    ASSERT_EQ(faces_in(view, input, box), kMiddle) << "the opening view skews the grid too much";

    std::optional<ViewerWindow> opened;
    auto viewer = open_grid(doc, opened);
    ASSERT_TRUE(opened && opened->ok());
    const ViewerWindow& window = *opened;
    std::string title;

    window.key("b");
    window.drag(box.x0, box.y0, box.x1, box.y1, 1);
    ASSERT_NO_FATAL_FAILURE(golden_view(*viewer, window, 1, "region_box"));

    window.key("shift+x");
    window.type("0.5");
    window.key("Return");
    ASSERT_TRUE(window.wait_title("V 48 E 84 F 37 *", false, 20s, &title)) << title << "\n"
                                                                           << viewer->err();
    ASSERT_NO_FATAL_FAILURE(golden_view(*viewer, window, 2, "region_extrude"));

    window.key("shift+w");  // the top stays selected: its nine quads become 36
    ASSERT_TRUE(window.wait_title("V 81 E 168 F 88 *", false, 20s, &title)) << title << "\n"
                                                                            << viewer->err();
    ASSERT_NO_FATAL_FAILURE(golden_view(*viewer, window, 3, "region_subdivide"));
    expect_replay_equals_saved(*viewer, window, original, doc);
}

// A lasso (Ctrl+right-drag) round the top-right 2 x 2, Shift+Delete: four holes that merge;
// Alt+click on an edge of the line x = 1: its loop of 5 edges, Delete dissolves them.
TEST_F(RegionE2E, LassoDeleteAndAltClickLoopDissolve) {
    const auto [original, doc] = grid_files();
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);
    const std::vector<std::uint32_t> corner = {18, 19, 23, 24};
    const Rect lasso = around(view, input, corner, 4);
    ASSERT_EQ(faces_in(view, input, lasso), corner);
    const Vertex a(2 * (kN + 1) + 1), b(3 * (kN + 1) + 1);  // (1, 2)-(1, 3)
    const std::optional<Pixel> on_edge = edge_pixel(view, input, a, b, Face(2 * kN + 1));
    ASSERT_TRUE(on_edge);

    std::optional<ViewerWindow> opened;
    auto viewer = open_grid(doc, opened);
    ASSERT_TRUE(opened && opened->ok());
    const ViewerWindow& window = *opened;
    std::string title;

    window.drag(lasso.x0, lasso.y0, lasso.x1, lasso.y1, 3, "ctrl");
    window.key("shift+Delete");
    ASSERT_TRUE(window.wait_title("F 21 *", false, 20s, &title)) << title << "\n" << viewer->err();

    window.modified_click(on_edge->x, on_edge->y, "alt");
    ASSERT_NO_FATAL_FAILURE(golden_view(*viewer, window, 1, "region_loop"));
    window.key("Delete");
    ASSERT_TRUE(window.wait_title("F 16 *", false, 20s, &title)) << title << "\n" << viewer->err();
    expect_replay_equals_saved(*viewer, window, original, doc);
}

// What a view shows is kept from one region to the next while the view stays, and dropped
// when the mesh changes: a box over the middle 3 x 3 and Shift+W (new faces, at new
// indices), Esc and the same box again: the session's last step selects the faces of the
// subdivided grid whose centres the box holds (kept points would hold the old nine).
TEST_F(RegionE2E, ARegionAfterAnEditSeesTheEditedMesh) {
    const auto [original, doc] = grid_files();
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);
    const Rect middle = around(view, input, kMiddle, 4);
    ASSERT_EQ(faces_in(view, input, middle), kMiddle);

    std::optional<ViewerWindow> opened;
    auto viewer = open_grid(doc, opened);
    ASSERT_TRUE(opened && opened->ok());
    const ViewerWindow& window = *opened;
    std::string title;
    window.key("b");
    window.drag(middle.x0, middle.y0, middle.x1, middle.y1, 1);
    window.key("shift+w");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title << "\n" << viewer->err();
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    const Mesh subdivided = load(doc);
    // What the box takes of the subdivided grid by region_pick's rule.
    const std::vector<ElementRef> expected =
        elements_in_box(subdivided, view.camera,
                        ScreenBox{{float(middle.x0), float(middle.y0)},
                                  {float(middle.x1), float(middle.y1)},
                                  kWidth,
                                  kHeight},
                        ElementRef::Kind::Face, Reach::Visible);
    ASSERT_GT(expected.size(), kMiddle.size());
    window.key("Escape");  // a box takes the selection's kind: none is faces
    window.key("b");
    window.drag(middle.x0, middle.y0, middle.x1, middle.y1, 1);
    const fs::path session = work_ / (doc.stem().string() + ".ops");
    ASSERT_NO_FATAL_FAILURE(answer_prompt(window, "ctrl+shift+e", std::nullopt));
    ASSERT_TRUE(wait_until([&] { return fs::exists(session); }, 20s)) << viewer->err();
    const std::string text = read_file(session);
    const std::string last = text.substr(text.rfind("select:"));
    EXPECT_EQ(last.substr(0, last.find_first_of(",\n")),
              ops::select_step_text(subdivided, expected));
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// The red line of a boundary edge is pickable from the line itself (issue 40): a click a
// pixel outside the grid's border, over no face, selects the border edge, and Delete
// dissolves it (its face joins the hole).
TEST_F(RegionE2E, ClickOnTheBorderLineSelectsTheBoundaryEdge) {
    const fs::path doc = work_ / "grid.obj";
    write_grid(doc);
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);
    const Vertex a(2), b(3);  // the bottom border's edge (2, 0)-(3, 0), beside face 2
    // A pixel whose centre lies outside the face but on the line (drawn 2.5 px wide): between
    // 0.3 and 1.1 px beyond the edge, near its middle.
    const glm::vec2 pa = view.pixel(input.position(a)), pb = view.pixel(input.position(b));
    const glm::vec2 mid = 0.5f * (pa + pb);
    glm::vec2 normal = glm::normalize(glm::vec2(pb.y - pa.y, pa.x - pb.x));
    if (glm::dot(normal, view.pixel(centroid(input, Face(2))) - mid) > 0) {
        normal = -normal;  // pointing away from the face
    }
    std::optional<Pixel> outside;
    for (int dy = -3; dy <= 3 && !outside; ++dy) {
        for (int dx = -3; dx <= 3 && !outside; ++dx) {
            const glm::vec2 centre(std::floor(mid.x) + dx + 0.5f, std::floor(mid.y) + dy + 0.5f);
            const float beyond = glm::dot(centre - mid, normal);
            if (beyond > 0.3f && beyond < 1.1f) {
                outside = clickable(view, centre);
            }
        }
    }
    ASSERT_TRUE(outside) << "no pixel centre on the outer half of the line";

    std::optional<ViewerWindow> opened;
    auto viewer = open_grid(doc, opened);
    ASSERT_TRUE(opened && opened->ok());
    const ViewerWindow& window = *opened;
    std::string title;
    window.click(outside->x, outside->y);
    window.key("Delete");
    ASSERT_TRUE(window.wait_title("F 24 *", false, 20s, &title)) << title << "\n" << viewer->err();
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title("V 36 E 60 F 25", false, 20s, &title)) << title;
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// A drag that starts on an unselected vertex orbits (issue 40: on a dense mesh the vertex
// radius covers the whole surface, and every orbit moved a vertex); a click selects the
// vertex, and a drag from it then moves it.
TEST_F(RegionE2E, OnlyTheSelectedVertexIsDragged) {
    const fs::path doc = work_ / "grid.obj";
    write_grid(doc);
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);
    const std::optional<Pixel> at = clickable(view, view.pixel(input.position(Vertex(14))));
    ASSERT_TRUE(at);

    std::optional<ViewerWindow> opened;
    auto viewer = open_grid(doc, opened);
    ASSERT_TRUE(opened && opened->ok());
    const ViewerWindow& window = *opened;
    std::string title;
    window.drag(at->x, at->y, at->x + 60, at->y + 30, 1);  // an orbit
    sleep_for(500ms);
    EXPECT_EQ(window.title().find('*'), std::string::npos) << window.title();
    window.key("space");  // the opening view again, so the vertex is where it was
    window.click(at->x, at->y);
    window.drag(at->x, at->y, at->x + 60, at->y + 30, 1);
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << "the selected vertex did not move";
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
