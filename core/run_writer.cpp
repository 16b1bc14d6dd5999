// PLACEHOLDER: being written (HDF5 writer). Replaced before the foundation lands.
#include "run_writer.h"
#include <stdexcept>
namespace collide {
struct RunWriter::Impl {};
RunWriter::RunWriter(const std::string& path, bool) { throw std::runtime_error(path + ": HDF5 writer not built yet"); }
RunWriter::~RunWriter() = default;
void RunWriter::write_attributes(const std::map<std::string, std::string>&) {}
void RunWriter::write_particles(const ParticleState<double>&) {}
void RunWriter::append(const Metrics&, const ParticleState<double>&) {}
void RunWriter::write_stats(const SolverStats&) {}
void RunWriter::commit() {}
}  // namespace collide
