#pragma once
// The bytes of the messages between ranks: fixed-size values in the machine's byte order and length-prefixed
// strings. Ranks of one job run the same binary (rank_agreement.h checks it), so no portable encoding is needed.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace isotrace {

class MessageWriter {
public:
    template <class T>
    MessageWriter& put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
        return *this;
    }
    MessageWriter& put_string(std::string_view text) {
        put(std::uint64_t(text.size()));
        bytes_.append(text);
        return *this;
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

// Throws std::runtime_error when the message ends early (a protocol bug, not user input).
class MessageReader {
public:
    explicit MessageReader(std::string_view bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        std::memcpy(&value, take(sizeof value).data(), sizeof value);
        return value;
    }
    std::string get_string() { return std::string(take(get<std::uint64_t>())); }

private:
    std::string_view take(std::size_t n) {
        if (n > bytes_.size() - at_) throw std::runtime_error("distributed render: a message between ranks is truncated");
        const std::string_view part = bytes_.substr(at_, n);
        at_ += n;
        return part;
    }
    std::string_view bytes_;
    std::size_t at_ = 0;
};

}  // namespace isotrace
