// Each family's rows of the radio registry (internal to src/radio; radio/registry.h is the table):
// radio/icom/models.cpp, radio/kenwood/models.cpp, radio/yaesu/models.cpp, radio/flex/models.cpp,
// radio/hamlib/models.cpp.
#pragma once
#include <span>

#include "radio/registry.h"

namespace tb::radio {

std::span<const RadioModel> icom_rows();
std::span<const RadioModel> kenwood_rows();
std::span<const RadioModel> yaesu_rows();
std::span<const RadioModel> flex_rows();
std::span<const RadioModel> hamlib_rows();

}  // namespace tb::radio
