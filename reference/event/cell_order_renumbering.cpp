#include "cell_order_renumbering.h"

namespace collide {

void CellOrderRenumbering::apply(EventArray<EventDisk>& disks, CellList& cells, EventQueue<EventSlot>& queue,
                                 const std::vector<std::vector<double>*>& per_disk,
                                 std::vector<std::uint32_t>& original) {
    events_since_ = 0;
    const std::size_t n = disks.size();
    if (n == 0) return;
    cells.cell_order(disks, order_);
    new_of_.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) new_of_[order_[k]] = k;

    disks_scratch_.resize(n);
    for (std::size_t k = 0; k < n; ++k) disks_scratch_[k] = disks[order_[k]];
    disks.swap(disks_scratch_);
    cells.relink_consecutive(disks, n);

    auto permute = [&](auto& v, auto& scratch) {
        scratch.resize(n);
        for (std::size_t k = 0; k < n; ++k) scratch[k] = v[order_[k]];
        v.swap(scratch);
    };
    for (std::vector<double>* a : per_disk) permute(*a, real_scratch_);
    permute(original, index_scratch_);
    queue.renumber(order_, new_of_);
    for (std::uint32_t k = 0; k < n; ++k) {
        EventPrediction& p = queue.payload(k).prediction;
        p.partner = new_of_[p.partner];
    }
}

}  // namespace collide
