#pragma once
#include <filesystem>
#include <string_view>

namespace isotrace {

// Writes `bytes` to `target` so that the target is afterwards either the complete new file or untouched.
// The bytes go to an unnamed file in the target's directory (O_TMPFILE), so that even SIGKILL during the write
// leaves nothing behind; once flushed to disk it is linked under a new hidden sibling name with a random suffix
// (".<stem>.partial-<random><ext>") and renamed over the target at once (rename replaces a symlink at `target`,
// never its referent). Where the file system has no O_TMPFILE, the sibling is created first, with
// O_CREAT|O_EXCL|O_NOFOLLOW so that no planted file or symlink is ever opened or followed. Any failure — disk
// full (ENOSPC), a file-size limit (EFBIG), an unwritable directory — removes what was written and throws
// std::runtime_error naming the target and the reason.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

// Async-signal-safe: removes the temporary siblings of the write_file_atomically calls in progress, for a signal
// handler that ends the process at once (so that a second Ctrl-C or SIGTERM during a write leaves nothing behind).
// Each call in progress publishes its temporary path in a fixed table of slots readable without locks.
void remove_temporary_files_in_progress() noexcept;

// Checks before any long work that write_file_atomically(target, ...) can succeed as far as permissions go: the
// target is not a directory and a file can be created beside it (found by creating and removing an empty probe,
// which also catches read-only file systems and ACLs, even for root). Throws std::runtime_error saying why not.
void check_atomically_writable(const std::filesystem::path& target);

}  // namespace isotrace
