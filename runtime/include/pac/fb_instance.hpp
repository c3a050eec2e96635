// One instance of a generated function block, set up the way MATIEC's interface requires: zeroed
// storage (so no member carries the force flag), then NAME_init__, then NAME_body__ once per call.
#pragma once

#include <cstring>
#include <type_traits>

namespace pac {

template <class Fb>
class FbInstance {
public:
    using InitFn = void (*)(Fb*, unsigned char);
    using BodyFn = void (*)(Fb*);

    FbInstance(InitFn init, BodyFn body) : body_(body) {
        static_assert(std::is_trivially_copyable<Fb>::value, "generated FB structs are plain C data");
        std::memset(&fb_, 0, sizeof fb_);
        init(&fb_, 0);
    }

    // Runs the FB body once: one scan's call.
    void operator()() { body_(&fb_); }

    Fb* operator->() { return &fb_; }
    const Fb* operator->() const { return &fb_; }
    Fb& Data() { return fb_; }

private:
    Fb fb_;
    BodyFn body_;
};

}  // namespace pac

// PAC_FB(FB_PAC_CMD) gives a ready FbInstance<FB_PAC_CMD>.
#define PAC_FB(TYPE) ::pac::FbInstance<TYPE>(TYPE##_init__, TYPE##_body__)
