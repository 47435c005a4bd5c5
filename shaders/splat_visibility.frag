// The soft splats' visibility pass (lod/point_line_lod.h) writes depth only; this fragment
// shader exists for the ID buffer (WRITE_ID) alone: the instance each visible splat belongs to.
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)

void main() { out_id = v_instance + 1u; }
