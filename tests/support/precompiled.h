// The headers every test compiles, precompiled once for all test programs (tests/CMakeLists.txt,
// flexure_test_pch). GoogleTest, Eigen and the standard library are about 180 000 of the 185 000
// preprocessed lines of a typical test file; parsing them once instead of in each of ~150 test
// files halves a test file's compile time. Only third-party and standard headers belong here: a
// flexure header in the precompiled header would hide a test's missing include of it.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>
