// Names of the standard frame log channels (docs/frame-log.md), shared by the simulation that
// writes them and the renderer that reads them.
#pragma once

namespace vascsim {

// Names of the standard frame log channels (docs/frame-log.md). A log holds only the channels
// its scene produces; readers must treat every channel but position as optional.
namespace channel {
inline constexpr const char* kPosition = "position";              // node vectors, m
inline constexpr const char* kVelocity = "velocity";              // node vectors, m/s
inline constexpr const char* kActuationForce = "force/actuation"; // node vectors, N (magnetic force)
inline constexpr const char* kContactForce = "force/contact";     // node vectors, N (wall normal force)
inline constexpr const char* kFrictionForce = "force/friction";   // node vectors, N
inline constexpr const char* kDragForce = "force/drag";           // node vectors, N
inline constexpr const char* kDampingForce = "force/damping";     // node vectors, N (viscous damping)
inline constexpr const char* kExternalForce = "force/external";   // node vectors, N (point loads, gravity)
inline constexpr const char* kMagnetForce = "force/magnet";       // node vectors, N (a tip magnet in the scene's fixed field)
inline constexpr const char* kTipReference = "tip/reference";     // vector, m (controller's target)
inline constexpr const char* kTipError = "tip/error";             // scalar, m (|tip - reference|)
inline constexpr const char* kFeedForce = "feed/force";           // scalar, N (control.advance: the drive's push along the inlet)
inline constexpr const char* kFeedLength = "feed/length";         // scalar, m (control.advance: the length fed so far)
}  // namespace channel

}  // namespace vascsim
