// SHA-256 (OpenSSL) and the random job ids.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace kontakt::server {

/// Lower-case hex SHA-256 of bytes / of a file's content.
std::string sha256_hex(std::string_view bytes);
std::string sha256_file(const std::filesystem::path& file);

/// 128 random bits from the OS's CSPRNG as 32 lower-case hex digits: unguessable job ids.
std::string new_job_id();
/// 32 lower-case hex digits.
bool is_job_id(std::string_view s);

}  // namespace kontakt::server
