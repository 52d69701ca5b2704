#include <spar/output/results_writer.hpp>

#include "format_double.hpp"
#include "layout_check.hpp"
#include "provenance_attributes.hpp"
#include "results_files.hpp"
#include "step_check.hpp"
#include "time_histories.hpp"
#include "writer_thread.hpp"
#include "written_files.hpp"

#include <spar/error.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <utility>

namespace spar::output {

namespace {

/// `path` with its extension replaced by `.xmf`.
std::string sidecar_path(const std::string& path) {
  return std::filesystem::path(path).replace_extension(".xmf").string();
}

}  // namespace

/// The writer's parts: the time histories and their buffers (the caller's), the files (written
/// by the writer thread's jobs, or by the caller with the writer thread idle) and the writer
/// thread with the block in flight.
struct ResultsWriter::Impl {
  Impl(const std::string& h5_path, ResultsLayout layout, int flush_every)
      : path(h5_path),
        xdmf_path(sidecar_path(h5_path)),
        append_where(detail::writer_where(h5_path, "append")),
        flush_every(flush_every),
        histories(std::move(layout)),
        files(path, xdmf_path) {}
  /// A constructor that threw after claiming the file leaves it to other writers.
  ~Impl() { detail::release_written_file(claim); }

  std::string path;          ///< as the caller gave it
  std::string xdmf_path;     ///< as xdmf_path() returns it
  std::string append_where;  ///< where append's errors happen
  int flush_every;
  bool closed = false;  ///< close() has run or an error closed the file
  std::string claim;    ///< the key of the HDF5 file in detail::written_files, until it is closed
  detail::TimeHistories histories;
  int appended = 0;
  int handed = 0;  ///< steps handed to the writer thread (the next block's first row)

  detail::ResultsFiles files;
  /// The block in flight: the caller fills it only once the writer thread has finished job
  /// `block_job`, which writes it.
  detail::Block block;
  std::uint64_t block_job = 0;
  int flushed = 0;  ///< steps on disk (written, H5Fflush-ed and in the sidecar): set by the block's job
  /// Last, so that it stops before the parts its jobs use are destroyed.
  detail::WriterThread writer;

  std::string where(const std::string& function) const { return detail::writer_where(path, function); }

  void require_open(const std::string& function) const {
    if (closed)
      throw Error("the results file is closed", where(function), "call " + function + " before close()");
  }

  /// Starts the writer thread (the constructor, once the path has proved writable) with the
  /// creation of the files as its first job. Both blocks' buffers are reserved whole, so append
  /// never reallocates.
  void start_writer() {
    std::vector<detail::Series>& series = histories.series();
    block.rows.resize(series.size());
    for (std::size_t k = 0; k < series.size(); ++k) {
      const auto values = static_cast<std::size_t>(flush_every) * series[k].values_per_step();
      series[k].buffer.reserve(values);
      block.rows[k].reserve(values);
    }
    writer.start([this] { files.create(histories, flush_every); });
  }

  /// Queues the root attribute `attribute` for the writer thread, after the jobs queued before
  /// it. A name HDF5 would refuse, or one of the provenance attributes, is refused here; an HDF5
  /// failure of the write is rethrown like any error of the writer thread.
  void queue_attribute(detail::RootAttribute attribute) {
    require_open("write_attribute");
    report_failure();
    detail::check_attribute_name(attribute.name, true, where("write_attribute"));
    writer.queue([this, attribute = std::move(attribute)] { files.write_attribute(attribute); });
  }

  /// Queues the run's options for the writer thread, like queue_attribute.
  void queue_options(RunOptions options) {
    require_open("write_options");
    report_failure();
    for (const auto& option : options) detail::check_attribute_name(option.first, false, where("write_options"));
    writer.queue([this, options = std::move(options)] { files.write_options(options); });
  }

  /// Hands the buffered steps to the writer thread as one block, once it has finished the
  /// previous one: the filled buffers and the written block's storage swap, so a step is copied
  /// once and, in steady state, nothing is allocated. Rethrows an earlier error of the writer
  /// thread instead (see report_failure).
  void hand_over() {
    if (appended == handed) return;
    writer.wait_for(block_job);
    report_failure();
    std::vector<detail::Series>& series = histories.series();
    block.first = handed;
    block.count = appended - handed;
    for (std::size_t k = 0; k < series.size(); ++k) {
      std::swap(block.rows[k], series[k].buffer);
      series[k].buffer.clear();  // keeps its capacity for the next block
    }
    block_job = writer.queue([this] {
      files.write_block(block, histories.series());
      flushed = block.first + block.count;
    });
    handed = appended;
  }

  /// Waits until the writer thread has done every job queued; if one failed, closes the file
  /// and rethrows its error.
  void wait_idle() {
    writer.wait_idle();
    report_failure();
  }

  /// Rethrows, after closing the file, an error the writer thread has met so far, without
  /// waiting for the job in hand.
  void report_failure() {
    if (std::exception_ptr error = writer.take_failure()) {
      release();
      std::rethrow_exception(error);
    }
  }

  /// Stops the writer thread, then closes the files and removes the spares; returns false if
  /// HDF5 reported a failure.
  bool release() {
    writer.stop();
    closed = true;
    const bool ok = files.release();
    detail::release_written_file(std::exchange(claim, {}));
    return ok;
  }

  /// A constant's values are finite (issue 29: a NaN constant was written silently).
  void check_constant(const std::string& name, const Eigen::MatrixXd& data) const {
    for (Eigen::Index j = 0; j < data.cols(); ++j)
      for (Eigen::Index i = 0; i < data.rows(); ++i)
        if (!std::isfinite(data(i, j)))
          throw Error("the constant " + name + " holds " + detail::format_double(data(i, j)) + " at row " +
                          std::to_string(i) + ", column " + std::to_string(j) + ", which is not finite",
                      where("write_constant"), "write finite values only");
  }
};

ResultsWriter::ResultsWriter(const std::string& h5_path, ResultsLayout layout, int flush_every) {
  const std::string where = "output::ResultsWriter(" + h5_path + ")";
  detail::check_layout(layout, flush_every, where);
  impl_ = std::make_unique<Impl>(h5_path, std::move(layout), flush_every);
  // What the caller can get wrong is refused here; the writer thread makes the files.
  impl_->claim = detail::claim_written_file(h5_path, where);
  impl_->files.check_writable(impl_->histories.layout());
  impl_->start_writer();
}

ResultsWriter::~ResultsWriter() {
  try {
    close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
}

ResultsWriter::ResultsWriter(ResultsWriter&&) noexcept = default;
ResultsWriter& ResultsWriter::operator=(ResultsWriter&& other) noexcept {
  if (this != &other) {
    ResultsWriter discarded(std::move(*this));  // closes the file this writer held
    impl_ = std::move(other.impl_);
  }
  return *this;
}

ResultsWriter::Impl& ResultsWriter::live(const std::string& function) const {
  if (!impl_)
    throw Error("this ResultsWriter was moved from and holds no file", "output::ResultsWriter::" + function,
                "call it on the writer it was moved to");
  return *impl_;
}

void ResultsWriter::write_attribute(const std::string& name, double value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_attribute(const std::string& name, std::int64_t value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_attribute(const std::string& name, const std::string& value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_options(const RunOptions& options) { live("write_options").queue_options(options); }

void ResultsWriter::write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                                   const std::string& description) {
  Impl& impl = live("write_constant");
  impl.require_open("write_constant");
  impl.check_constant(name, data);
  impl.wait_idle();
  impl.files.write_constant(name, data, unit, description);
}

void ResultsWriter::append(const ResultsStep& step) {
  Impl& impl = live("append");
  impl.require_open("append");
  impl.report_failure();
  detail::check_step(impl.histories.layout(), step,
                     {.where = impl.append_where, .index = impl.appended, .last_time = impl.histories.last_time()});
  impl.histories.place_shapes(step, impl.append_where);
  impl.histories.buffer(step);
  ++impl.appended;
  if (impl.appended - impl.handed >= impl.flush_every) impl.hand_over();
}

void ResultsWriter::flush() {
  Impl& impl = live("flush");
  impl.require_open("flush");
  impl.hand_over();
  impl.wait_idle();
}

void ResultsWriter::close() {
  if (!impl_ || impl_->closed) return;
  std::exception_ptr failure;
  try {
    flush();
  } catch (...) {
    failure = std::current_exception();
  }
  const bool released = impl_->closed || impl_->release();  // a writer-thread error released it already
  if (failure) std::rethrow_exception(failure);
  detail::check_writer_call(released ? 0 : -1, "close the file", impl_->path, "close");
}

int ResultsWriter::steps_written() const { return live("steps_written").appended; }

int ResultsWriter::steps_flushed() const {
  const Impl& impl = live("steps_flushed");
  impl.writer.wait_idle();
  return impl.flushed;
}

const std::string& ResultsWriter::xdmf_path() const { return live("xdmf_path").xdmf_path; }

}  // namespace spar::output
