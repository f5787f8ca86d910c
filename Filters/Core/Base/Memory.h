// Checking a large allocation against the memory the system has, so that a scene too big
// for the machine gets a clear error instead of std::bad_alloc or the OOM killer.
#ifndef RadiosityCore_Memory_h
#define RadiosityCore_Memory_h

#include <string>

namespace radiosity
{

/// Memory the system can give now without swapping (Linux MemAvailable), in bytes; 0 when
/// it cannot be read.
double AvailableMemory();

/// Empty when `bytes` fit in 90 % of the available memory (or it is unknown); otherwise an
/// error naming `what`, its size and what is available.
std::string CheckMemory(double bytes, const std::string& what);
/// The same against `limit` bytes where it is positive (a cap the caller chose), else as above.
std::string CheckMemory(double bytes, const std::string& what, double limit);

} // namespace radiosity

#endif
