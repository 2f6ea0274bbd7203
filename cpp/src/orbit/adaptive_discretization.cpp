// Adaptive placement of visibility volumes along the POI path (section IV.B, metric (56)).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <tbb/parallel_for.h>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

namespace {

struct Sample {
  double s;
  int depth;
};

// Arc lengths s_i of the path nodes.
std::vector<double> node_arc_lengths(const PoiPath& poi) {
  std::vector<double> s;
  for (double t : poi.node_times()) s.push_back(t * poi.speed());
  return s;
}

// Every `spacing` metres from the start of each edge, plus every node: the samples of a coarser
// spacing that divides a finer one are a subset of the finer one's (Figure 4 reuses VVs).
std::vector<Sample> initial_samples(const PoiPath& poi, double spacing) {
  const std::vector<double> nodes = node_arc_lengths(poi);
  std::vector<Sample> out;
  for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
    const double length = nodes[e + 1] - nodes[e];
    const auto steps = static_cast<long long>(std::ceil(length / spacing - 1e-9));
    for (long long k = 0; k < steps; ++k) out.push_back({nodes[e] + static_cast<double>(k) * spacing, 0});
  }
  out.push_back({nodes.back(), 0});
  return out;
}

class Refiner {
 public:
  Refiner(const PoiPath& poi, VolumeCache& cache, const MetricFunction& metric, const ProgressFunction& progress)
      : poi_(poi), cache_(cache), metric_(metric), progress_(progress) {
    if (!metric_) throw Error("metric function is empty");
  }

  // VVs of the samples without one yet, in parallel.
  void fill_volumes(const std::vector<Sample>& samples, std::map<long long, VolumePtr>& volumes) {
    std::vector<double> missing;
    for (const Sample& sample : samples)
      if (!volumes.count(key(sample.s))) missing.push_back(sample.s);
    std::vector<VolumePtr> made(missing.size());
    std::vector<char> fresh(missing.size(), 0);
    needed_ += missing.size();
    report();
    // Chunks keep the progress bar moving on long batches.
    const std::size_t chunk = 16;
    for (std::size_t first = 0; first < missing.size(); first += chunk) {
      const std::size_t last = std::min(missing.size(), first + chunk);
      tbb::parallel_for(first, last, [&](std::size_t i) {
        bool computed = false;
        made[i] = cache_.at(poi_.position(missing[i] / poi_.speed()), &computed);
        fresh[i] = computed ? 1 : 0;
      });
      done_ += last - first;
      report();
    }
    for (std::size_t i = 0; i < missing.size(); ++i) {
      volumes[key(missing[i])] = made[i];
      computed_ += static_cast<std::size_t>(fresh[i]);
    }
  }

  std::vector<double> metrics(const std::vector<std::pair<VolumePtr, VolumePtr>>& pairs) {
    std::vector<double> out(pairs.size());
    tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
      const double d = metric_(*pairs[i].first, *pairs[i].second);
      if (!std::isfinite(d)) throw Error("metric: not a finite number between neighbouring VVs");
      out[i] = d;
    });
    return out;
  }

  static long long key(double s) { return std::llround(s * 1e6); }
  std::size_t computed() const { return computed_; }

 private:
  void report() {
    if (progress_) progress_(done_, needed_);
  }
  const PoiPath& poi_;
  VolumeCache& cache_;
  const MetricFunction& metric_;
  const ProgressFunction& progress_;
  std::size_t needed_ = 0, done_ = 0, computed_ = 0;
};

Discretization discretize(const PoiPath& poi, double spacing, double cutoff, double min_spacing, int max_depth,
                          VolumeCache& cache, const MetricFunction& metric, const ProgressFunction& progress) {
  Refiner refiner(poi, cache, metric, progress);
  std::vector<Sample> samples = initial_samples(poi, spacing);
  std::map<long long, VolumePtr> volumes;
  std::map<long long, double> metric_after;  // metric between a sample and the next one
  refiner.fill_volumes(samples, volumes);

  // Breadth-first halving: the same set of samples as the paper's recursion (each interval is
  // split independently of the others), but each level's new VVs are computed in parallel.
  std::vector<std::size_t> open(samples.size() > 1 ? samples.size() - 1 : 0);
  for (std::size_t i = 0; i < open.size(); ++i) open[i] = i;
  while (!open.empty()) {
    std::vector<std::pair<VolumePtr, VolumePtr>> pairs;
    for (std::size_t i : open) pairs.emplace_back(volumes.at(Refiner::key(samples[i].s)), volumes.at(Refiner::key(samples[i + 1].s)));
    const std::vector<double> d = refiner.metrics(pairs);
    std::vector<Sample> inserted;
    std::vector<std::size_t> split;  // index into `open`
    for (std::size_t j = 0; j < open.size(); ++j) {
      const Sample& a = samples[open[j]];
      const Sample& b = samples[open[j] + 1];
      metric_after[Refiner::key(a.s)] = d[j];
      const int depth = std::max(a.depth, b.depth);
      const double half = 0.5 * (b.s - a.s);
      if (d[j] > cutoff && depth < max_depth && half >= min_spacing) {
        inserted.push_back({a.s + half, depth + 1});
        split.push_back(j);
      }
    }
    if (inserted.empty()) break;
    refiner.fill_volumes(inserted, volumes);
    // Rebuild the ordered samples and the intervals to examine next (both halves of each split).
    std::vector<Sample> merged;
    merged.reserve(samples.size() + inserted.size());
    std::vector<std::size_t> next_open;
    std::size_t next_split = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      merged.push_back(samples[i]);
      if (next_split < split.size() && open[split[next_split]] == i) {
        next_open.push_back(merged.size() - 1);
        merged.push_back(inserted[next_split]);
        next_open.push_back(merged.size() - 1);
        ++next_split;
      }
    }
    samples = std::move(merged);
    open = std::move(next_open);
  }

  Discretization out;
  out.points.resize(static_cast<Eigen::Index>(samples.size()), 3);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    out.arc_lengths.push_back(samples[i].s);
    out.times.push_back(samples[i].s / poi.speed());
    out.points.row(static_cast<Eigen::Index>(i)) = poi.position(out.times.back()).transpose();
    out.depths.push_back(samples[i].depth);
    out.volumes.push_back(volumes.at(Refiner::key(samples[i].s)));
    if (i + 1 < samples.size()) out.metric.push_back(metric_after.at(Refiner::key(samples[i].s)));
  }
  out.volumes_computed = refiner.computed();
  return out;
}

// Samples a halving of an interval of `length` m may add in the worst case: 2^k - 1 for the k
// halvings allowed (depth < max_depth, halves >= min_spacing).
double worst_insertions(double length, double min_spacing, int max_depth) {
  int halvings = 0;
  while (halvings < max_depth && length / std::ldexp(1.0, halvings + 1) >= min_spacing) ++halvings;
  return std::ldexp(1.0, halvings) - 1.0;
}

// Initial samples (as initial_samples places them, counted without building them) and, when
// min_spacing is given, the worst-case insertions into every interval.
double count_samples(const PoiPath& poi, double spacing, double min_spacing, int max_depth) {
  const std::vector<double> nodes = node_arc_lengths(poi);
  double count = 1.0;  // the last node
  for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
    const double length = nodes[e + 1] - nodes[e];
    const double steps = std::ceil(length / spacing - 1e-9);
    count += steps;
    if (max_depth > 0 && steps >= 1.0) {
      const double last = length - (steps - 1.0) * spacing;  // the edge's last, shorter interval
      count += (steps - 1.0) * worst_insertions(spacing, min_spacing, max_depth) +
               worst_insertions(last, min_spacing, max_depth);
    }
  }
  return count;
}

std::string count_text(double value) {
  std::ostringstream out;
  out.precision(value < 1e15 ? 15 : 3);
  out << value;
  return out.str();
}

}  // namespace

WorkEstimate estimate_work(const PoiPath& poi, const Planning& planning) {
  planning.validate();
  WorkEstimate work;
  work.volumes = count_samples(poi, planning.spacing, planning.min_spacing, planning.max_depth);
  work.bytes_per_volume = volume_bytes(planning.resolution_deg);
  work.initial_volumes = count_samples(poi, planning.spacing, planning.spacing, 0);
  work.spacing = planning.spacing;
  work.resolution_deg = planning.resolution_deg;
  return work;
}

WorkEstimate estimate_fixed_work(const PoiPath& poi, double spacing, double resolution_deg) {
  require_length(spacing, "spacing");
  WorkEstimate work;
  work.volumes = work.initial_volumes = count_samples(poi, spacing, spacing, 0);
  work.bytes_per_volume = volume_bytes(resolution_deg);
  work.spacing = spacing;
  work.resolution_deg = resolution_deg;
  return work;
}

void check_work(const WorkEstimate& work, std::size_t max_volumes, const std::string& field) {
  // The worst-case count first: max_volumes is the limit a user may raise explicitly.
  if (work.volumes > static_cast<double>(max_volumes))
    detail::fail_field(field, max_volumes,
                       "this plan may need up to " + count_text(std::ceil(work.volumes)) + " VVs, holding about " +
                           count_text(std::ceil(work.bytes() / 1e9)) +
                           " GB (a path length / min_spacing of VVs at most, ~4.7 MB each at 1 degree); raise " +
                           field + " explicitly to allow it, or raise the spacing or min_spacing");
  // Then the bytes of the VVs every plan computes (one every spacing, held to the end), which no
  // limit raises: a grid finer than 1 degree is named when it makes each VV larger than the
  // default's (0.1 degree: 100 times), else the spacing.
  const double per_degree = volume_bytes(kDefaultResolutionDeg);
  const bool grid = work.bytes_per_volume > per_degree * (1.0 + 1e-9);
  require_work_bytes(work.initial_bytes(), grid ? "planning.resolution_deg" : "planning.spacing",
                     grid ? detail::to_text(work.resolution_deg) : detail::to_text(work.spacing),
                     "the plan's first " + count_text(work.initial_volumes) + " VVs (one every spacing, " +
                         limits::bytes_text(work.bytes_per_volume) + " each)",
                     grid ? "a coarser resolution_deg (1 degree: " + limits::bytes_text(per_degree) +
                                " per VV) or a larger planning.spacing"
                          : "a larger planning.spacing, or a shorter path");
}

Discretization adaptive_discretization(const PoiPath& poi, const Planning& planning, VolumeCache& cache,
                                       const MetricFunction& metric, const ProgressFunction& progress) {
  check_work(estimate_work(poi, planning), planning.max_volumes);
  return discretize(poi, planning.spacing, planning.cutoff, planning.min_spacing, planning.max_depth, cache, metric,
                    progress);
}

Discretization fixed_discretization(const PoiPath& poi, double spacing, VolumeCache& cache,
                                    const MetricFunction& metric, const ProgressFunction& progress,
                                    std::size_t max_volumes) {
  // The grid of the cache is not known here: the estimate counts 1-degree VVs.
  check_work(estimate_fixed_work(poi, spacing, kDefaultResolutionDeg), max_volumes, "max_volumes");
  return discretize(poi, spacing, std::numeric_limits<double>::infinity(), spacing, 0, cache, metric, progress);
}

}  // namespace vistrack
