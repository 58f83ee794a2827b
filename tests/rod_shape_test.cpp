// The initial shape (sim/rod/rod_model.cpp, docs/scenes.md "shape"): with an initial curvature,
// `direction` is the heading of the first edge, the edge a clamp holds (issue 16 item 5e: the
// chords used to start from the arc's tangent, half a chord turn, asin(kappa dl / 2), earlier),
// the centred clamp straddles `start` and every node lies on the arc's circle.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/run/compile.h"
#include "sim/step/model.h"

namespace vascsim {
namespace {

TEST(RodShape, DirectionIsTheFirstEdgesHeadingOnACurvedRod) {
  for (const ClampKind clamp : {ClampKind::kCentred, ClampKind::kFirstEdge, ClampKind::kNone}) {
    Scene scene;
    scene.has_environment = false;
    scene.rod.nodes = 21;
    scene.boundary.clamp = clamp;
    scene.shape.start = Vec2(0.1, -0.2);
    scene.shape.direction = 0.3;            // rad
    scene.shape.initial_curvature = 4.0;    // 1/m: the 0.5 m rod turns through 2 rad
    const Model model = *compile(scene);
    const State state = initial_state(model);
    const Vec2 a = state.position(0), b = state.position(1);
    const Vec2 e = b - a;
    EXPECT_NEAR(std::atan2(e.y(), e.x()), 0.3, 1e-14);
    const Vec2 root = clamp == ClampKind::kCentred ? Vec2(0.5 * (a + b)) : a;
    EXPECT_NEAR((root - scene.shape.start).norm(), 0.0, 1e-15);
    // Chords dl of a circle of radius R = 1/kappa: its centre lies on the first chord's
    // perpendicular bisector, sqrt(R^2 - (dl/2)^2) to the left (positive curvature turns left).
    const double r = 1.0 / scene.shape.initial_curvature, dl = model.rod.edge_length;
    const Vec2 left = Vec2(-e.y(), e.x()) / e.norm();
    const Vec2 centre = 0.5 * (a + b) + std::sqrt(r * r - 0.25 * dl * dl) * left;
    for (int i = 0; i < model.nodes(); ++i) EXPECT_NEAR((state.position(i) - centre).norm(), r, 1e-12) << i;
  }
}

}  // namespace
}  // namespace vascsim
