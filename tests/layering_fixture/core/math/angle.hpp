#pragma once
// An include that goes up: math may not use util.
#include "core/util/clock.hpp"
