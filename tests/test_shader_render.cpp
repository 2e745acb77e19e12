// The renderer's --model shader: the specular pass through the Verilated spec_shader equals the pass through
// the bit-exact models (setup model, then the core's model) pixel for pixel, and the default scene through it
// stays within 4 levels of 255 of the double-precision reference in ecp5 (issue 13, item 4) and within 6 in up5k
// (issue 28, item 4).
#include <gtest/gtest.h>

#include "raster.h"
#include "scene.h"
#include "setup_render.h"
#include "stats.h"

using namespace spec;

TEST(ShaderRender, RtlEqualsModelsAndStaysNearRef) {
    const render::Scene sc = render::make_scene("default");
    const render::Frame f = render::rasterize(sc, 192, 192);
    const render::Shading base = render::shade_base(sc, f);
    const render::SpecRun rtl = shade_shader(sc, f, SetupConfig::ecp5, render::RgbMode::once, host::GammaRule::patent);
    const render::SpecRun mod = shade_shader_models(sc, f, SetupConfig::ecp5, render::RgbMode::once, host::GammaRule::patent);
    ASSERT_EQ(rtl.spec, mod.spec) << "the Verilated shader and the models differ";
    EXPECT_EQ(rtl.core_pixels, mod.core_pixels);
    EXPECT_GT(rtl.core_cycles, rtl.core_pixels);
    const render::SpecRun ref = render::shade_specular(sc, f, render::SpecModel::ref, render::RgbMode::once);
    const render::ImageStats st = render::compare(render::compose(base, rtl), render::compose(base, ref), base.covered);
    EXPECT_LE(st.max_abs, 4);
    RecordProperty("max_levels", std::to_string(st.max_abs));
}

TEST(ShaderRender, Up5kEqualsItsModelsAndStaysNearRef) {
    const render::Scene sc = render::make_scene("default");
    const render::Frame small = render::rasterize(sc, 40, 40);
    const render::SpecRun rtl = shade_shader(sc, small, SetupConfig::up5k, render::RgbMode::once, host::GammaRule::patent);
    const render::SpecRun mod = shade_shader_models(sc, small, SetupConfig::up5k, render::RgbMode::once, host::GammaRule::patent);
    ASSERT_EQ(rtl.spec, mod.spec);
    // the default scene through the up5k models (equal to its RTL above) against the reference
    const render::Frame f = render::rasterize(sc, 192, 192);
    const render::Shading base = render::shade_base(sc, f);
    const render::SpecRun m = shade_shader_models(sc, f, SetupConfig::up5k, render::RgbMode::once, host::GammaRule::patent);
    const render::SpecRun ref = render::shade_specular(sc, f, render::SpecModel::ref, render::RgbMode::once);
    const render::ImageStats st = render::compare(render::compose(base, m), render::compose(base, ref), base.covered);
    EXPECT_LE(st.max_abs, 6);
    RecordProperty("max_levels", std::to_string(st.max_abs));
}
