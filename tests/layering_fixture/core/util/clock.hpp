#pragma once
#include "core/math/angle.hpp"
