// The live view's page (web/live_view.html), compiled in by CMake (live_view_page.cpp.in) so pac-sim needs no
// files beside it.
#pragma once

namespace pac::pacsim {

const char* LiveViewPage();

}  // namespace pac::pacsim
