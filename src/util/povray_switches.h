// POV-Ray's own spellings of the options `mirage trace` and `mirage compile` share (+W640,
// +H480, +A0.3, +AM2, +R3, +Oout.png, +K0.5, +Lpath, Declare=NAME=VALUE), translated to the
// commands' long options before the command line is parsed, so that a POV-Ray user's habits
// work and every value is still checked where the long option is read.
#pragma once

#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

/// The command whose long options the switches become: they differ for the image (trace's
/// --output, compile's --image) and for antialiasing (compile's corrected camera averages
/// fixed rays: it takes POV-Ray's default threshold, and no method or depth).
enum class SwitchTarget { Trace, Compile };

/// The words after the subcommand's name with POV-Ray's switches translated:
///   +Wn -> --width=n, +Hn -> --height=n, +Ofile -> --output=file (compile: --image=file),
///   +Kx -> --clock=x, +Lpath -> --library-path=path, Declare=N=V -> --declare=N=V,
///   +A -> --antialias, +Ax -> --antialias=x (compile: x must be 0.3),
///   +AMn -> --antialias-method=n, +Rn -> --antialias-depth=n (trace only);
///   -D and -A (display and antialiasing off) -> nothing, -J -> --no-jitter (trace; compile:
///   nothing); an .ini's keys as POV-Ray's command line takes them too, Width=, Height=,
///   Output_File_Name=, Clock=, Library_Path=, Antialias=on|off, Antialias_Threshold=,
///   Antialias_Depth=, Sampling_Method=, Jitter=on|off, as the switches above.
/// The letters are read in either case, as POV-Ray reads them; the value is attached, as
/// POV-Ray takes it (`+W 640` is refused, saying so).  Words after "--" and the word after an
/// option of `value_options` (the command's options that take a value: "-o", "--output", ...)
/// are values, left as they are.  Any other word of '+' and a letter is refused as a POV-Ray
/// switch the command does not take (a file whose name starts so is given as ./+name).  An
/// error names the word.
Result<std::vector<std::string>> translate_povray_switches(
    const std::vector<std::string>& words, SwitchTarget target,
    const std::vector<std::string>& value_options);

}  // namespace mirage
