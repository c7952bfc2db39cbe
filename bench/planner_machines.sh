# The machines of the planner benchmarks, sourced by planner_optimum.sh and scurve_reference.sh:
# X Y Z at 100 mm/s and 500 mm/s², jerk 50,000 and 5,000 mm/s³, written as DIR/j50000.toml and
# DIR/j5000.toml.
write_planner_machines() {
  local dir=$1 jerk ax
  for jerk in 50000 5000; do
    {
      printf '[machine]\nname = "optimum-bench"\nservo_period_s = 0.001\n\n'
      for ax in X Y Z; do
        printf '[[axis]]\nname = "%s"\nkind = "linear"\nmax_velocity = 100\nmax_acceleration = 500\n' "$ax"
        printf 'max_jerk = %s\nmin = -1000.0\nmax = 1000.0\nsteps_per_unit = 1000.0\n\n' "$jerk"
      done
    } > "$dir/j$jerk.toml"
  done
}
