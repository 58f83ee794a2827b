// Placeholder so that the render library target exists before the renderer lands.
namespace vascsim::render {
int render_library_version() { return 0; }
}  // namespace vascsim::render
