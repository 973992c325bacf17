#pragma once
// Test helper: the InputError an action throws, for tests that then check its position and wording.
#include <gtest/gtest.h>

#include <string>

#include "renderer/core/input_error.h"

namespace isotrace::testing {

// The error `action` throws; a test failure naming `what` (and an empty error) when it throws none.
template <class Action>
InputError input_error_of(Action&& action, const std::string& what) {
    try {
        action();
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no error for " << what;
    return InputError({}, "", "");
}

}  // namespace isotrace::testing
