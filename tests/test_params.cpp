#include <gtest/gtest.h>

#include "params.hpp"
