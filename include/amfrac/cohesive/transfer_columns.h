#pragma once

#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /** The sum of one member over the ledgers of all interfaces. */
  template <typename Ledger, typename Member>
  double
  total(const std::vector<Ledger> &ledger, const Member member)
  {
    double sum = 0;
    for (const Ledger &l : ledger)
      sum += l.*member;
    return sum;
  }

  /** The columns adaptivity.csv gives an interface transfer, in static and
   * explicit runs alike: the dissipated energy, the debonded and the
   * damaged area over all interfaces before and after the mesh change, and
   * the transfer's report (CohesiveInterfaces::TransferReport). */
  template <typename Ledger, typename Report>
  std::vector<std::pair<std::string, double>>
  interface_transfer_columns(const std::vector<Ledger> &before,
                             const std::vector<Ledger> &after,
                             const Report              &report)
  {
    return {{"dissipated_before", total(before, &Ledger::dissipated)},
            {"dissipated_after", total(after, &Ledger::dissipated)},
            {"debonded_before", total(before, &Ledger::debonded)},
            {"debonded_after", total(after, &Ledger::debonded)},
            {"damaged_before", total(before, &Ledger::damaged)},
            {"damaged_after", total(after, &Ledger::damaged)},
            {"injected_points", double(report.injected)},
            {"aggregated_points", double(report.aggregated)},
            {"beyond_history", double(report.beyond_history)},
            {"interface_force_imbalance", report.force_imbalance}};
  }
} // namespace amfrac
