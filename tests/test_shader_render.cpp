// The renderer's --model shader: the specular pass through the Verilated spec_shader equals the pass through
// the bit-exact models (setup model, then the core's model) pixel for pixel, and the default scene through it
// stays within 4 levels of 255 of the double-precision reference (issue 13, item 4).
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
    const render::SpecRun rtl = shade_shader(sc, f, SetupConfig::pipelined, render::RgbMode::once, host::GammaRule::patent);
    const render::SpecRun mod = shade_shader_models(sc, f, SetupConfig::pipelined, render::RgbMode::once, host::GammaRule::patent);
    ASSERT_EQ(rtl.spec, mod.spec) << "the Verilated shader and the models differ";
    EXPECT_EQ(rtl.core_pixels, mod.core_pixels);
    EXPECT_GT(rtl.core_cycles, rtl.core_pixels);
    // one pixel per clock after the latency (about 280 clocks) of each batch of 4096 spans the renderer sends
    const uint64_t batches = (f.spans.size() + 4095) / 4096;
    EXPECT_LT(rtl.core_cycles, rtl.core_pixels + 350 * batches) << "the pipelined shader: one pixel per clock";
    const render::SpecRun ref = render::shade_specular(sc, f, render::SpecModel::ref, render::RgbMode::once);
    const render::ImageStats st = render::compare(render::compose(base, rtl), render::compose(base, ref), base.covered);
    EXPECT_LE(st.max_abs, 4);
    RecordProperty("max_levels", std::to_string(st.max_abs));
}

TEST(ShaderRender, SmallConfigurationEqualsItsModels) {
    const render::Scene sc = render::make_scene("default");
    const render::Frame f = render::rasterize(sc, 40, 40);
    const render::SpecRun rtl = shade_shader(sc, f, SetupConfig::small, render::RgbMode::once, host::GammaRule::patent);
    const render::SpecRun mod = shade_shader_models(sc, f, SetupConfig::small, render::RgbMode::once, host::GammaRule::patent);
    ASSERT_EQ(rtl.spec, mod.spec);
}
