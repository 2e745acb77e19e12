parallax_step.v
parallax_iter.v
