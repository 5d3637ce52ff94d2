#pragma once
// Material edges (a house on a slope): where the painted colour alone may
// not tell two materials apart (a stiff house moves with the soil and gets
// the soil's displacement colour), a line is drawn wherever two materials
// touch. Empty space draws no line: against the background a body shows by
// itself, and the gaps of torn soil stay as painted.
#include <cstdint>
#include <vector>

#include "render/image.hpp"
#include "render/splat.hpp"
#include "render/viewport.hpp"

namespace render {

// Draws the edges into img within `clip`, `thickness` px wide, half on
// each material's side. Points are the splat's squares (snap_square),
// `material` one id per point. A no-op when points.material is null.
void draw_material_edges(Image& img, const PixelMap& map, const Rect& clip,
                         const PointsView& points, Rgba ink, int thickness);

}  // namespace render
