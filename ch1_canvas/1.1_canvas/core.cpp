#include "core.h"

namespace engine {

Core::Core(browser::Canvas& context) : context_(context) {}

double Core::width() const { return context_.width(); }
double Core::height() const { return context_.height(); }

}  // namespace engine
