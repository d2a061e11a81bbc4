#pragma once
// One error type for the whole core: the message names the file or argument and the reason,
// so the caller can show it to the user once, as it is.
#include <stdexcept>
#include <string>

namespace aniso
{
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// "subject: reason", the format every user-facing error uses.
inline Error errorAbout(const std::string& subject, const std::string& reason)
{
  return Error(subject + ": " + reason);
}
} // namespace aniso
