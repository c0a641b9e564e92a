#pragma once
// CONTACT's example inputs and reference outputs (../shared/reference/contact-examples) for the
// tests that read them. Tests skip, saying why, when the folder is absent.

#include <gtest/gtest.h>

#include <filesystem>

namespace rollcontact::test_support {

inline const std::filesystem::path kExamples = ROLLCONTACT_EXAMPLES_DIR;

}  // namespace rollcontact::test_support

#define REQUIRE_EXAMPLES()                                                                 \
  if (!std::filesystem::is_directory(::rollcontact::test_support::kExamples)) {            \
    GTEST_SKIP() << "example folder not found: " << ::rollcontact::test_support::kExamples \
                 << " (CONTACT's examples, ../shared/reference/contact-examples)";         \
  }
