#include "lib/truth/effect.h"
#include <gtest/gtest.h>
namespace insmc { namespace { TEST(Effect, Placeholder) {} } }
