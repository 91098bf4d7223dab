# Perturbs a TUM trajectory like dead reckoning would: re-integrates its relative motions
# with a scale error, a yaw drift per pose and Gaussian noise, starting from a rigid offset.
# usage: awk -v seed=1 -v scale=1.01 -v yaw_drift=0.002 -v sigma=0.01 -f perturb-tum.awk IN.tum
# Variables (defaults): seed 1, scale 1, yaw_drift 0 rad/pose, sigma 0 (m, and rad/10),
# off_x 5, off_y -3, off_yaw 0.5 (the rigid offset of the first pose).
function gauss() { return sqrt(-2 * log(1 - rand())) * cos(6.283185307179586 * rand()) }
BEGIN {
  srand(seed == "" ? 1 : seed)
  if (scale == "") scale = 1
  if (off_x == "") off_x = 5
  if (off_y == "") off_y = -3
  if (off_yaw == "") off_yaw = 0.5
  print "# timestamp x y z qx qy qz qw"
}
/^[ \t]*#/ || NF == 0 { next }
{
  t = $1; x = $2; y = $3; a = 2 * atan2($7, $8)
  if (n == 0) {
    c = cos(off_yaw); s = sin(off_yaw)
    X = off_x + c * x - s * y; Y = off_y + s * x + c * y; A = a + off_yaw
  } else {
    dx = x - px; dy = y - py; c = cos(pa); s = sin(pa)
    lx = scale * (c * dx + s * dy) + sigma * gauss()
    ly = scale * (-s * dx + c * dy) + sigma * gauss()
    da = atan2(sin(a - pa), cos(a - pa)) + yaw_drift + 0.1 * sigma * gauss()
    X += cos(A) * lx - sin(A) * ly; Y += sin(A) * lx + cos(A) * ly; A += da
  }
  printf "%.6f %.9g %.9g 0 0 0 %.9g %.9g\n", t, X, Y, sin(A / 2), cos(A / 2)
  px = x; py = y; pa = a; n++
}
