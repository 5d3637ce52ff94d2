#pragma once
// Outlines of a secondary material (a house on a slope): where the painted
// colour alone may not tell two materials apart (a stiff house moves with the
// soil and gets the soil's displacement colour), a line is drawn wherever a
// region of material id > 0 meets another material or empty space. Material 0
// (the bulk, the soil) gets no line against empty space, so the plot of a
// single material is left exactly as painted.
#include <cstdint>
#include <vector>

#include "render/image.hpp"
#include "render/splat.hpp"
#include "render/viewport.hpp"

namespace render {

// Draws the outlines into img within `clip`, `thickness` px wide on the
// secondary material's side. Points are the splat's squares (snap_square),
// `material` one id per point. A no-op when points.material is null.
void draw_material_edges(Image& img, const PixelMap& map, const Rect& clip,
                         const PointsView& points, Rgba ink, int thickness);

}  // namespace render
