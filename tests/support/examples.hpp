#pragma once
// CONTACT's example inputs and reference outputs (../shared/reference/contact-examples) for the
// tests that read them. Tests skip, saying why, when the folder is absent.

#include <gtest/gtest.h>

#include <filesystem>

namespace rollcontact::test_support {

inline const std::filesystem::path kExamples = ROLLCONTACT_EXAMPLES_DIR;

}  // namespace rollcontact::test_support

/// Skips the current test, saying why and how to run it, when CONTACT's example folder is absent.
#define REQUIRE_EXAMPLES()                                                                    \
  if (!std::filesystem::is_directory(::rollcontact::test_support::kExamples)) {               \
    GTEST_SKIP() << "CONTACT's example folder is absent ("                                    \
                 << ::rollcontact::test_support::kExamples                                    \
                 << "): this reference test is skipped. To run it, place CONTACT's examples " \
                    "(reference/contact-examples: .inp inputs and .ref_out reports) at that " \
                    "path, next to the repository.";                                          \
  }
