#pragma once
// Registry: creates plugins (cameras, shapes, materials, lights, integrators, pixel filters, samplers) from
// their scene "type" string. Plugins register themselves from their own folder with ISOTRACE_REGISTER_PLUGIN;
// the core never names a concrete type.
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/core/did_you_mean.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

template <class Product, class... Args>
class Registry {
public:
    using Factory = std::function<std::unique_ptr<Product>(const SceneNode&, Args...)>;

    struct Entry {
        Factory factory;
        std::string summary;  // one line for `isotrace info --plugins` and docs
    };

    explicit Registry(std::string kind) : kind_(std::move(kind)) {}

    // Two plugins under one name is a programming error: the second would silently shadow the first.
    void add(const std::string& type, Factory factory, std::string summary) {
        if (!entries_.emplace(type, Entry{std::move(factory), std::move(summary)}).second)
            throw std::logic_error(kind_ + " type \"" + type + "\" is registered twice");
    }

    bool contains(const std::string& type) const { return entries_.count(type) != 0; }

    std::vector<std::string> types() const {
        std::vector<std::string> names;
        for (const auto& [name, entry] : entries_) names.push_back(name);
        return names;
    }

    const std::map<std::string, Entry>& entries() const { return entries_; }
    const std::string& kind() const { return kind_; }

    // Creates the plugin named by node["type"] (or `default_type` when the key is absent and a default is
    // given), then rejects keys the plugin did not read.
    std::unique_ptr<Product> create(const SceneNode& node, Args... args, const std::string& default_type = {}) const {
        const std::string type = default_type.empty() ? node.string("type") : node.string_or("type", default_type);
        const auto found = entries_.find(type);
        if (found == entries_.end()) {
            std::string list;
            for (const auto& name : types()) list += (list.empty() ? "" : ", ") + name;
            node.fail_at("type", "unknown " + kind_ + " type \"" + type + "\"" + did_you_mean(type, types()) +
                                     "; available: " + list);
        }
        std::unique_ptr<Product> product = found->second.factory(node, args...);
        node.finish();
        return product;
    }

private:
    std::string kind_;
    std::map<std::string, Entry> entries_;
};

}  // namespace isotrace

#define ISOTRACE_PLUGIN_CONCAT_INNER(a, b) a##b
#define ISOTRACE_PLUGIN_CONCAT(a, b) ISOTRACE_PLUGIN_CONCAT_INNER(a, b)

// Registers `factory` under `type` in the registry returned by `registry_function()` at library load time.
// The factory is variadic so that commas inside a lambda body need no extra parentheses.
#define ISOTRACE_REGISTER_PLUGIN(registry_function, type, summary, ...)                                   \
    namespace {                                                                                           \
    const bool ISOTRACE_PLUGIN_CONCAT(isotrace_registered_, __LINE__) =                                   \
        (registry_function().add(type, __VA_ARGS__, summary), true);                                      \
    }
