#pragma once
// Ctrl-C / SIGTERM as a request to stop cleanly: the run checkpoints at its
// next birth (the births in flight kept) and exits 130. The first signal only sets a flag; the
// handler then restores the default action, so a second Ctrl-C kills at once
// (the last checkpoint stays valid either way). `evolve` and `resume` make one
// first thing, before they read or create anything, so a signal during
// start-up is a stop request like any other, never a death by the signal.
// Only a signal in the first 10-25 ms, while the system still loads the
// program and its libraries (before main), ends it by the signal (before anything is written); a launcher
// that blocks SIGINT/SIGTERM across exec closes that gap too, since the
// constructor unblocks them.
namespace morphogen {

class StopSignals {
public:
    // Installs the handlers, clears the flag, unblocks SIGINT/SIGTERM; a
    // signal the process started with ignored is left ignored. The
    // handlers stay until the process exits (the destructor leaves them): a
    // signal that comes after the work is done, while the process tears down,
    // changes nothing and must not turn a finished run into a killed one.
    StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    static bool requested();
    static int signal_number();  // the signal received (0 if none)
};

}  // namespace morphogen
