// The kept frame (ui/retained_frame.hpp) and the one-pass overlay (Renderer::
// set_one_pass_overlay) against the full frame: a workstation that redraws only what changed
// must show the very pixels of one that draws everything, frame after frame, while a point is
// dragged, the indicator moves and a panel's field changes; the overlay drawn in one pass must
// match its two depth-tested passes. Needs headless OpenGL (EGL); skipped without it.
#include <gtest/gtest.h>

#include <cfloat>
#include <imgui.h>
#include <memory>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/frame_damage.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/headless/offscreen_target.hpp"
#include "ui/image/png_compare.hpp"
#include "ui/render/gl.hpp"
#include "ui/render/renderer.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/workstation.hpp"

namespace isoparm::ui {
namespace {

constexpr int frame_w = 1000, frame_h = 700;

// A workstation of its own (own ImGui context) on fig3b, drawing into its own target.
struct Station {
    OffscreenTarget target{frame_w, frame_h};
    std::unique_ptr<Workstation> ws;

    Station(bool retained, bool one_pass) {
        WorkstationOptions o{/*headless=*/true, 1.f, ViewMode::workstation, /*msaa=*/0, {}};
        o.retained = retained;
        ws = std::make_unique<Workstation>(o);
        ws->context().renderer->set_one_pass_overlay(one_pass);
        auto d = scene::load_scene(ISOPARM_SOURCE_DIR "/assets/scenes/fig3b-weight-5.json");
        EXPECT_TRUE(d.ok());
        if (d.ok()) ws->context().doc = std::move(d).value();
        normalize_selection(ws->context().doc);
    }
    RgbImage frame() {
        ws->make_current();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(frame_w, frame_h);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        ws->frame(target.fbo());
        RgbImage img{frame_w, frame_h, {}};
        std::vector<unsigned char> rgba(static_cast<std::size_t>(frame_w) * frame_h * 4);
        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo());
        glReadPixels(0, 0, frame_w, frame_h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        for (std::size_t k = 0; k < rgba.size(); k += 4)
            img.rgb.insert(img.rgb.end(), {rgba[k], rgba[k + 1], rgba[k + 2]});
        return img;
    }
    void move_point(double dz) {
        AppContext& ctx = ws->context();
        const doc::Object* obj = nullptr;
        const geom::Surface* s = current_surface(ctx.doc, &obj);
        ASSERT_TRUE(s);
        const glm::dvec3 p = s->point(1, 1);
        ctx.execute(doc::move_control_point(obj->id, 1, 1, p + glm::dvec3(0, 0, dz)));
    }
};

std::unique_ptr<EglContext> context_or_skip() {
    std::string error;
    auto egl = EglContext::create(error);
    return egl;
}

TEST(RetainedFrame, ShowsTheFullFramesPixelsThroughADrag) {
    const auto egl = context_or_skip();
    if (!egl) GTEST_SKIP() << "no headless OpenGL";
    Station full(false, true), kept(true, true);
    for (int f = 0; f < 3; ++f) {
        const ImageComparison c = compare_images(full.frame(), kept.frame(), 0, 0);
        EXPECT_TRUE(c.match) << "settling frame " << f << ": " << c.summary;
    }
    for (int step = 1; step <= 4; ++step) {
        full.move_point(0.05 * step);
        kept.move_point(0.05 * step);
        const ImageComparison c = compare_images(full.frame(), kept.frame(), 0, 0);
        EXPECT_TRUE(c.match) << "drag step " << step << ": " << c.summary;
    }
    for (Station* s : {&full, &kept}) s->ws->context().doc.view.indicator = {0.2, 0.7};
    ImageComparison c = compare_images(full.frame(), kept.frame(), 0, 0);
    EXPECT_TRUE(c.match) << "indicator moved: " << c.summary;
    // Nothing changed: the kept picture stands, and it is still the full frame's.
    c = compare_images(full.frame(), kept.frame(), 0, 0);
    EXPECT_TRUE(c.match) << "still frame: " << c.summary;
}

TEST(RetainedFrame, OnePassOverlayMatchesTheTwoDepthTestedPasses) {
    const auto egl = context_or_skip();
    if (!egl) GTEST_SKIP() << "no headless OpenGL";
    Station two(false, false), one(false, true);
    for (int f = 0; f < 3; ++f) {
        two.frame();
        one.frame();
    }
    two.move_point(-0.4); // the net's parts behind the surface drawn faint
    one.move_point(-0.4);
    const RgbImage a = two.frame(), b = one.frame();
    // Blending order differs only where a hidden and a visible fragment of one batch share a
    // pixel, and a fragment exactly at the scene's depth may fall to either side.
    const ImageComparison c = compare_images(a, b, 8, 0.0005);
    EXPECT_TRUE(c.match) << c.summary;
}

TEST(FrameDamage, MergesOverlapsAndKeepsAtMostTheRectanglesAsked) {
    const std::vector<PixelRect> r =
        merge_rects({{0, 0, 10, 10}, {5, 5, 20, 20}, {100, 100, 110, 110}, {}}, 3);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0], (PixelRect{0, 0, 20, 20}));
    EXPECT_EQ(r[1], (PixelRect{100, 100, 110, 110}));
    const std::vector<PixelRect> one =
        merge_rects({{0, 0, 10, 10}, {50, 0, 60, 10}, {200, 200, 210, 210}}, 1);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0], (PixelRect{0, 0, 210, 210}));
}

TEST(FrameDamage, ChangedListsDamageTheirOldAndNewBoundsAndReorderingEverything) {
    const PixelRect frame{0, 0, 500, 400};
    const DrawListPrint a{"A#0", 1, {0, 0, 50, 50}, {}}, b{"B#0", 2, {100, 100, 150, 150}, {}};
    EXPECT_TRUE(damage({a, b}, {a, b}, frame).empty());
    DrawListPrint b2 = b;
    b2.hash = 3;
    b2.bounds = {120, 100, 170, 150};
    const std::vector<PixelRect> d = damage({a, b}, {a, b2}, frame);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0], b.bounds);
    EXPECT_EQ(d[1], b2.bounds);
    EXPECT_EQ(damage({a, b}, {a}, frame), std::vector<PixelRect>{b.bounds}); // b went
    EXPECT_EQ(damage({a, b}, {b, a}, frame), std::vector<PixelRect>{frame}); // restacked
    DrawListPrint image = a;
    image.volatile_px = {10, 10, 20, 20};
    EXPECT_EQ(damage({image}, {image}, frame), std::vector<PixelRect>{image.volatile_px});
}

} // namespace
} // namespace isoparm::ui
