#pragma once
// An OSMesa GL 3.3 core context, current on construction. Only this folder sees OSMesa; the
// renderer draws into whatever context is current.

#include <cstdint>
#include <vector>

namespace meshedit::headless {

class OsMesaContext {
public:
    /// Creates a core-profile 3.3 context with a `width` × `height` RGBA default buffer
    /// (the renderer draws into its own FBO; the buffer only makes the context current).
    /// \throws GlError if OSMesa cannot create or bind the context.
    OsMesaContext(int width, int height);
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;
    ~OsMesaContext();

    /// Waits until every GL command has finished (glFinish), for timings.
    void finish() const;

private:
    void* context_ = nullptr;  ///< OSMesaContext, kept opaque so the header needs no GL
    std::vector<std::uint8_t> buffer_;
};

}  // namespace meshedit::headless
