function seed000_curves(ll, rpm, step_deg, csv, scaled)
% The rows of `shaper curves` computed as seed 000's main program six_bar_main does
% them: one call of the seed's subroutine six_bar per crank angle and speed (on the
% path, extracted from the seed file at run time by benchmarks/test_bench_peer_octave.py;
% its code is not copied here), then every row written to a CSV file. Only a benchmark's.
%
% ll = [l1 l3 l4 l6 l61] in m, as six_bar takes them (crank, lever, rod, frame, guide);
% rpm: crank speeds, r/min; step_deg: crank-angle step, degrees; csv: output file.
% Crank angle phi (deg) is counted from the limit position that begins the cutting
% stroke, as `shaper curves` counts it: the seed's theta1 = phi - theta/2, with theta
% = 2 asin(l1/l6) the extreme-position angle. The seed's frame and signs are kept (x
% toward the seed's return side, lengths in m); the test maps them onto ours.
% Unlike six_bar_main, the arrays are allocated once instead of grown row by row,
% which is what a careful user would do for 72 002 rows (and faster for Octave).
% With scaled = true, six_bar is called once per angle (at omega1 = 1 rad/s) and its
% rates are scaled by omega and omega^2 for every speed, as `shaper curves` does; the
% seed's program has no such step (it is run once per speed), so the default is false.
if nargin < 5
  scaled = false;
end
theta = 2 * asin(ll(1) / ll(4));
phi_deg = (0:round(360 / step_deg)) * step_deg;
n = numel(phi_deg);
rows = zeros(n * numel(rpm), 14);
omega = rpm * 2 * pi / 60;
if scaled
  for i = 1:n
    [th, om, al] = six_bar(phi_deg(i) * pi / 180 - theta / 2, 1, 0, ll);
    for j = 1:numel(rpm)
      rows((j - 1) * n + i, :) = [rpm(j), phi_deg(i), th(:)', omega(j) * om(:)', ...
                                  omega(j)^2 * al(:)'];
    end
  end
else
  k = 0;
  for j = 1:numel(rpm)
    for i = 1:n
      [th, om, al] = six_bar(phi_deg(i) * pi / 180 - theta / 2, omega(j), 0, ll);
      k = k + 1;
      rows(k, :) = [rpm(j), phi_deg(i), th(:)', om(:)', al(:)'];
    end
  end
end
fid = fopen(csv, 'w');
fprintf(fid, ['rpm,crank_deg,s3_m,theta3_rad,theta4_rad,sE_m,v2_m_s,omega3_rad_s,' ...
              'omega4_rad_s,vE_m_s,a2_m_s2,alpha3_rad_s2,alpha4_rad_s2,aE_m_s2\n']);
fprintf(fid, [repmat('%.10g,', 1, 13), '%.10g\n'], rows');
fclose(fid);
end
