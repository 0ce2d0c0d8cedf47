#pragma once
/// @file AtomicFile.h
/// @brief Writing a file so that it is either the old one or the whole new one, never half.

#include <filesystem>
#include <string_view>

namespace thyrix {

/// Writes @p content to `<path>.tmp` in the same directory, then renames it over @p path, so a
/// reader (or a run killed at any moment) sees either the previous file or the complete new
/// one.
/// @throws std::runtime_error naming the path if the file cannot be written or renamed (the
///         temporary file is then removed and @p path left as it was)
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

}  // namespace thyrix
