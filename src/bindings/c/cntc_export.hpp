#pragma once
// Marks the C routines the shared library exports; everything else stays hidden.

#include "rollcontact/contact_addon.h"

#define CNTC_EXPORT extern "C" __attribute__((visibility("default")))
