#pragma once
// Test helper: sets or unsets an environment variable for one scope and restores it afterwards,
// so tests of $OCIO handling do not depend on, or leak into, the environment they run in.
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

namespace isotrace {

class ScopedEnvironmentVariable {
public:
    // std::nullopt unsets the variable.
    ScopedEnvironmentVariable(std::string name, const std::optional<std::string>& value)
        : name_(std::move(name)) {
        if (const char* previous = std::getenv(name_.c_str())) previous_ = previous;
        apply(value);
    }
    ~ScopedEnvironmentVariable() { apply(previous_); }
    ScopedEnvironmentVariable(const ScopedEnvironmentVariable&) = delete;
    ScopedEnvironmentVariable& operator=(const ScopedEnvironmentVariable&) = delete;

private:
    void apply(const std::optional<std::string>& value) const {
        if (value)
            setenv(name_.c_str(), value->c_str(), 1);
        else
            unsetenv(name_.c_str());
    }

    std::string name_;
    std::optional<std::string> previous_;
};

}  // namespace isotrace
