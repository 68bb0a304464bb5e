// The host loop shared by every contact-producing style (pair tri/gran, fix tri/wall): a list
// of body-pair tasks evaluated on OpenMP threads, each thread with scratch of its own, errors
// caught per task, results tallied and forces summed in an order that does not depend on the
// thread count. A style keeps only what differs: where its tasks come from and what its second
// body is (its host, below).
//
// Phases: tasks run in groups of consecutive ones (tasks_per_group: kGroupTasks, fewer on
// several threads when tasks are few), on one thread each (the schedule: split_groups below).
// Within a group the engine plans every task (body_interaction.h: plan_body_pair, through the
// host); a plan is a finished result or a kernel request, which the engine queues
// (kernel_queue.h). Then it runs the group's queued kernel jobs together (retries and
// fallbacks fill the vector lanes across body pairs) and finishes each requesting task from its
// results (finish_body_pair), in the order the requests were queued. The results are bitwise
// those of each task run alone.
//
// The host, for each task k of [0, n), on the thread that runs it (`thread`: 0 to threads - 1):
//   PairPlan plan(std::size_t k, int thread, InteractionScratch &, ContactStats &);
//     the host's own per-task work (bodies built, proven_apart asked), then the pair's plan:
//     an apart_result, or plan_body_pair's outcome;
//   PairForceResult finish(std::size_t k, const KernelRequest &, const TrianglePairDistance
//                          *results, InteractionScratch &, ContactStats &);
//     for a task whose plan was a request: finish_body_pair with the same bodies and kept
//     state as the plan (the request's pairs may have moved: use the one given);
//   void complete(std::size_t k, PairForceResult &result);
//     once the task's result is final, before it is stored: the host's bookkeeping of it.
// The scratch is the thread's; the stats take the distance kernel's counters.
//
// Determinism: every task writes its result into its own slot; the tally is summed over the
// slots in fixed blocks of tasks, each in task order, the blocks in order, and the per-atom sums
// in (atom, partner) order (stable: equal keys keep the order they were contributed in), so the
// forces and the tally are bitwise the same for any thread count. Both sums run on the run's
// threads (each a share of the blocks or of the atoms).
// Errors: an exception thrown by the host or the kernel does not leave the parallel region (it
// would end in std::terminate); a task that throws is not planned further, a kernel run that
// throws fails every task of its group that requested it. The engine keeps the message of the
// lowest failing task, and the host reports it through its own error path after the loop,
// naming the bodies of that task.
// Memory: scratch and queues grow to the largest task and group seen and are kept (bytes()).
#pragma once

#include "interaction/body_interaction.h"
#include "interaction/interaction_tally.h"
#include "interaction/kernel_queue.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace tri {

class InteractionEngine {
public:
  // Runs tasks [0, n) through `host` (header). threads <= 1: the calling thread alone, no
  // parallel region.
  template <class Host> void run(std::size_t n, int threads, Host &&host);

  // Tasks per group: enough queued kernels to fill the retry and fallback lanes and to fetch
  // the jobs' triangles well ahead (distance_kernels.cpp), few enough that a group's triangles
  // are still in cache when its tasks go on. Paired runs against 16: the formed hopper and the
  // settled pile 4-5 % faster at 32, 64 no better.
  static constexpr long kGroupTasks = 32;
  // On several threads, smaller groups where there are few tasks (a wall's, or a small pile's):
  // at least kGroupsPerThread each, down to kMinGroupTasks, so that the last group a thread
  // takes is a small part of its share. With 197 wall tasks in groups of 32 (7 groups), one
  // of 2 threads waited for the other 6-20 % of the walls' time.
  static constexpr long kGroupsPerThread = 8;
  static constexpr long kMinGroupTasks = 8;
  static long tasks_per_group(long tasks, int threads) {
    return threads <= 1 ? kGroupTasks
                        : std::max(kMinGroupTasks,
                                   std::min(kGroupTasks, tasks / (kGroupsPerThread * threads)));
  }

  std::size_t size() const { return results_.size(); }
  const PairForceResult &result(std::size_t k) const { return results_[k]; }

  bool failed() const { return failed_task_ < results_.size(); }
  std::size_t failed_task() const { return failed_task_; } // lowest failing task
  const std::string &failure() const { return failure_; }

  // Statistics of the last run.
  const InteractionTally &tally() const { return tally_; }

  // Ordered summation of the results' forces. Task k's result acts on up to two atoms: a takes
  // force_a and torque_a, b takes -force_a and torque_b; set_recipients(k, ...) names them and
  // their partners (-1: no atom; a wall's task names a only), any time after run() and before
  // apply(), on any thread (each task its own slot), by default none. apply() adds them to f
  // and torque (rows indexed by atom) in (atom, partner) order, ties in task order (a before
  // b): the sums do not depend on the thread count. apply() runs on the last run's threads,
  // each summing a share of the atoms, where the tasks are many.
  void set_recipients(std::size_t k, int a, long long partner_of_a, int b, long long partner_of_b) {
    recipients_[k] = {a, b, partner_of_a, partner_of_b};
  }
  void apply(double **f, double **torque);

  // Per-contact records (contact_force.h ContactRecord): set before run(), every task's contact
  // points are recorded (InteractionScratch::record_contacts) and kept until the next run; off,
  // nothing is recorded and records(k) is empty. What the virial and contact outputs read.
  void record_contacts(bool on) { record_ = on; }
  bool recording() const { return record_; }
  struct Records {
    const ContactRecord *first = nullptr;
    std::size_t count = 0;
    const ContactRecord *begin() const { return first; }
    const ContactRecord *end() const { return first + count; }
  };
  Records records(std::size_t k) const;
  // With records, after apply(): the tasks' virials (Virial: each side's records summed in their
  // order) added to `global` (6 values) in task order, and to vatom (rows by atom) in apply()'s
  // order, for the sides that apply() gave a recipient: so the sums do not depend on the thread
  // count, and a contact that apply() gives a rank's atom counts there only.
  void add_virial(double *global, double **vatom) const;

  std::size_t bytes() const; // heap memory held

private:
  struct Recipients {
    int a = -1, b = -1;
    long long partner_of_a = 0, partner_of_b = 0;
  };
  struct Contribution { // one side of a task: its atom, partner, task and side (0: a, 1: b)
    int atom;
    long long partner;
    std::uint32_t task;
    int side;
  };
  std::vector<InteractionScratch> scratch_; // one per thread
  // One per thread, each on cache lines of its own: every task adds to its thread's counters,
  // and two threads writing one line (the end of one entry, the start of the next) would pass
  // it back and forth.
  struct alignas(64) ThreadStats : ContactStats {};
  std::vector<ThreadStats> thread_stats_;
  // One per thread: the group's kernel requests, and the task of each.
  struct alignas(64) ThreadQueue {
    KernelQueue kernels;
    std::vector<long> tasks;
  };
  std::vector<ThreadQueue> queues_;
  std::vector<PairForceResult> results_;
  std::vector<Recipients> recipients_; // per task
  bool record_ = false;
  struct RecordRange { // task k's records: scratch_[thread].records[begin, end)
    int thread = 0;
    std::uint32_t begin = 0, end = 0;
  };
  std::vector<RecordRange> record_ranges_; // per task, while recording
  Virial side_virial(const Contribution &c) const;
  // apply(): one thread's contiguous share of the atoms, its named sides in task order, their
  // indices sorted by (atom, partner), and the counting sort's offsets (by atom - first).
  struct alignas(64) AtomShare {
    std::vector<Contribution> contributions;
    std::vector<std::uint32_t> sorted;
    std::vector<std::size_t> first_of_atom, next_of_atom;
  };
  std::vector<AtomShare> shares_;
  int used_shares_ = 0; // by the last apply()
  int threads_ = 1;     // of the last run
  // apply() sums on the run's threads from this many tasks a thread: below, the fork costs
  // more than the sums.
  static constexpr std::size_t kApplyTasksPerThread = 256;
  void sum_share(AtomShare &share, int first_atom, int last_atom, double **f, double **torque);
  InteractionTally tally_;
  static constexpr std::size_t kTallyTasks = 256; // finish(): tasks per block of the tally
  std::vector<InteractionTally> block_tallies_;
  std::size_t failed_task_ = 0;
  std::string failure_;

  // The schedule on several threads. Each thread owns a contiguous range of groups and takes
  // them from its front; once done it takes the last groups of the others' ranges. A host
  // lists its tasks in LIGGGHTS's atom order, which the atom sort keeps spatial, so a thread's
  // own range shares bodies, whose triangles and state then stay in that core's cache (with
  // groups handed out one by one, a settled pile on 2 threads spent a third more CPU time,
  // mostly waiting for lines the other core had written). Taking from the back keeps the
  // owner's remaining groups contiguous and balances uneven ranges (a hopper's tasks crowd
  // where the pile is). Front and back share one atomic word, so a group is taken once.
  struct alignas(64) GroupRange {
    std::atomic<std::uint64_t> bounds{0}; // front << 32 | back, groups [front, back) left
  };
  std::unique_ptr<GroupRange[]> ranges_;
  int num_ranges_ = 0;
  void split_groups(long groups, int threads);
  long take_group(int range, int thread); // the next group of `range` for `thread`, or -1

  void prepare(std::size_t n, int threads);
  void record_failure(std::size_t k, const char *what);
  void finish();
  // step() for task k, an exception failing the task.
  template <class Step> void guarded(std::size_t k, Step &&step);
  // Task k's final result, from `host` on `thread`, whose records since `recorded` are its own.
  template <class Host>
  void conclude(std::size_t k, int thread, std::size_t recorded, PairForceResult result,
                Host &host);
  template <class Host>
  void run_group(long g, long group_tasks, long count, int thread, Host &host);
};

template <class Step> void InteractionEngine::guarded(std::size_t k, Step &&step) {
  try {
    step();
  } catch (const std::exception &e) {
    record_failure(k, e.what());
  } catch (...) {
    record_failure(k, "unknown exception");
  }
}

template <class Host>
void InteractionEngine::conclude(std::size_t k, int thread, std::size_t recorded,
                                 PairForceResult result, Host &host) {
  host.complete(k, result);
  results_[k] = result;
  if (record_)
    record_ranges_[k] = {thread, static_cast<std::uint32_t>(recorded),
                         static_cast<std::uint32_t>(scratch_[thread].records.size())};
}

template <class Host>
void InteractionEngine::run_group(long g, long group_tasks, long count, int thread, Host &host) {
  InteractionScratch &scratch = scratch_[thread];
  ContactStats &stats = thread_stats_[thread];
  ThreadQueue &queue = queues_[thread];
  queue.kernels.clear();
  queue.tasks.clear();
  const long first = g * group_tasks, last = std::min(count, first + group_tasks);
  for (long k = first; k < last; ++k)
    guarded(k, [&] {
      const std::size_t recorded = scratch.records.size();
      PairPlan plan = host.plan(static_cast<std::size_t>(k), thread, scratch, stats);
      if (const KernelRequest *request = std::get_if<KernelRequest>(&plan)) {
        queue.kernels.add(*request);
        queue.tasks.push_back(k);
      } else {
        conclude(k, thread, recorded, std::get<PairForceResult>(plan), host);
      }
    });
  if (queue.kernels.empty())
    return;
  try {
    queue.kernels.run(stats);
  } catch (const std::exception &e) {
    for (long k : queue.tasks)
      record_failure(static_cast<std::size_t>(k), e.what());
    return;
  }
  for (std::size_t j = 0; j < queue.tasks.size(); ++j) {
    const long k = queue.tasks[j];
    guarded(k, [&] {
      const std::size_t recorded = scratch.records.size();
      conclude(k, thread, recorded,
               host.finish(static_cast<std::size_t>(k), queue.kernels.request(j),
                           queue.kernels.results(j), scratch, stats),
               host);
    });
  }
}

template <class Host> void InteractionEngine::run(std::size_t n, int threads, Host &&host) {
  if (threads < 1)
    threads = 1;
  prepare(n, threads);
  threads_ = threads;
  const long count = static_cast<long>(n);
  const long group_tasks = tasks_per_group(count, threads);
  const long groups = (count + group_tasks - 1) / group_tasks;
  if (threads == 1) {
    for (long g = 0; g < groups; ++g)
      run_group(g, group_tasks, count, 0, host);
  } else {
    split_groups(groups, threads);
#pragma omp parallel num_threads(threads)
    {
      int thread = 0;
#ifdef _OPENMP
      thread = omp_get_thread_num();
#endif
      for (long g; (g = take_group(thread, thread)) >= 0;)
        run_group(g, group_tasks, count, thread, host);
      for (int other = 1; other < threads; ++other)
        for (long g; (g = take_group((thread + other) % threads, thread)) >= 0;)
          run_group(g, group_tasks, count, thread, host);
    }
  }
  finish();
}

} // namespace tri
