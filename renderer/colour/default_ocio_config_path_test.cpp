#include "renderer/colour/default_ocio_config_path.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "renderer/colour/colour_system.h"
#include "tests/support/scoped_environment_variable.h"

namespace OCIO = OCIO_NAMESPACE;

namespace isotrace {
namespace {

bool is_shipped_config(const std::string& path) {
    const std::filesystem::path p(path);
    return p.filename() == "isotrace.ocio" && p.parent_path().filename() == "ocio" &&
           std::filesystem::is_regular_file(p);
}

TEST(DefaultOcioConfigPath, WithoutOcioVariableUsesTheShippedConfig) {
    ScopedEnvironmentVariable unset("OCIO", std::nullopt);
    EXPECT_TRUE(is_shipped_config(default_ocio_config_path())) << default_ocio_config_path();
}

TEST(DefaultOcioConfigPath, EmptyOcioVariableCountsAsUnset) {
    ScopedEnvironmentVariable empty("OCIO", "");
    EXPECT_TRUE(is_shipped_config(default_ocio_config_path())) << default_ocio_config_path();
}

TEST(DefaultOcioConfigPath, OcioVariableOverridesTheShippedConfig) {
    std::string shipped;
    {
        ScopedEnvironmentVariable unset("OCIO", std::nullopt);
        shipped = default_ocio_config_path();
    }
    // A copy of the shipped config with one extra colour space, so we can tell which one loaded.
    OCIO::ConfigRcPtr config = OCIO::Config::CreateFromFile(shipped.c_str())->createEditableCopy();
    OCIO::ColorSpaceRcPtr extra = OCIO::ColorSpace::Create();
    extra->setName("Override Test Space");
    config->addColorSpace(extra);

    const std::filesystem::path override_path =
        std::filesystem::temp_directory_path() /
        ("isotrace_ocio_override_" + std::to_string(::getpid()) + ".ocio");
    {
        std::ofstream file(override_path);
        config->serialize(file);
    }

    {
        ScopedEnvironmentVariable override_ocio("OCIO", override_path.string());
        EXPECT_EQ(default_ocio_config_path(), override_path.string());

        const ColourSystem colour(std::string{});
        EXPECT_EQ(colour.config_path(), override_path.string());
        EXPECT_TRUE(colour.has_colour_space("Override Test Space"));
    }
    std::filesystem::remove(override_path);
}

}  // namespace
}  // namespace isotrace
