// CAT wire formats of the radios TrakBox drives, one codec per family: Icom CI-V
// (radio/icom/codec.h), Kenwood (radio/kenwood/codec.h), Yaesu FT-736/FT-847/FT-817
// (radio/yaesu/codec.h), on the shared byte helpers of radio/bytes.h. Pure functions; the byte
// strings of docs/radio.md ("CAT formats") are their unit tests (tests/unit/radio/test_cat.cpp).
#pragma once
#include "radio/bytes.h"
#include "radio/icom/codec.h"
#include "radio/kenwood/codec.h"
#include "radio/yaesu/codec.h"
