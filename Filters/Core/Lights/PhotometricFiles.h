// Reading photometric files: IES LM-63 (1986, 1991, 1995, 2002, 2019) and EULUMDAT, into
// the one PhotometricWeb every light kind uses.
#ifndef RadiosityCore_PhotometricFiles_h
#define RadiosityCore_PhotometricFiles_h

#include "Lights/Photometry.h"

#include <functional>
#include <string>

namespace radiosity
{

/// Reads a file's text by name (TILT=<file> names a second file beside the first); false
/// where it cannot.
using TextReader = std::function<bool(const std::string& path, std::string& text)>;

/// Empty, or the problem as "<name>:<line>: <what>". `name` is for messages and for
/// finding a TILT file (through `read`, relative to name's folder).
std::string ParseIes(const std::string& text, const std::string& name, PhotometricWeb& out, const TextReader& read);
std::string ParseEulumdat(const std::string& text, const std::string& name, PhotometricWeb& out);

/// Reads `path` from disk as IES or EULUMDAT, by its extension (.ies, .ldt; any case),
/// else by its first line. Empty, or the problem naming the file (and line).
std::string ReadPhotometricFile(const std::string& path, PhotometricWeb& out);

/// Reads a whole file into `text`; false where it cannot be opened or is over 64 MiB.
bool ReadTextFile(const std::string& path, std::string& text);

} // namespace radiosity

#endif
