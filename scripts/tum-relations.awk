# Writes Freiburg-style relations "t1 t2 x y z roll pitch yaw" from a TUM trajectory taken
# as the truth: the pose `gap` poses later expressed in the frame of each `every`-th pose.
# usage: awk -v gap=5 -v every=1 -f tum-relations.awk GT.tum > GT.relations
/^[ \t]*#/ || NF == 0 { next }
{ t[n + 0] = $1; x[n + 0] = $2; y[n + 0] = $3; a[n + 0] = 2 * atan2($7, $8); n++ }
END {
  if (gap == "") gap = 5
  if (every == "") every = 1
  print "# timestamp1 timestamp2 x y z roll pitch yaw"
  for (i = 0; i + gap < n; i += every) {
    j = i + gap; dx = x[j] - x[i]; dy = y[j] - y[i]; c = cos(a[i]); s = sin(a[i])
    da = atan2(sin(a[j] - a[i]), cos(a[j] - a[i]))
    printf "%.6f %.6f %.9g %.9g 0 0 0 %.9g\n", t[i], t[j], c * dx + s * dy, -s * dx + c * dy, da
  }
}
