#pragma once
// SIGINT, SIGTERM and SIGUSR1 (the signal Slurm sends ahead of a job's time limit) turned into
// a request that the coupled run polls between DEM steps: it then writes a checkpoint and
// stops, instead of dying with the stage's work lost.
namespace wear::coupling {

class StopSignals {
public:
  /// Installs the handlers; the previous ones come back when this object goes.
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// The signal received since construction, 0 if none.
  int requested() const;
  /// "SIGTERM" etc.
  static const char* name(int signal);
};

} // namespace wear::coupling
