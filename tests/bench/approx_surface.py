# The peer of bench_fitting: FreeCAD's ReverseEngineering.approxSurface on the benchmark's point
# sets (caseK.xyz in the folder given), with its default smoothing and without, 12 x 12 cubic
# poles like every method there. Writes caseK_smooth.brep / caseK_raw.brep and the seconds each
# call took (approx_times.txt); a call that raises writes nothing for that case.
import sys, time, traceback
import Part, ReverseEngineering

folder, count, poles = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
times = []
for k in range(count):
    pts = []
    with open("%s/case%d.xyz" % (folder, k)) as f:
        for line in f:
            x, y, z = map(float, line.split())
            pts.append((x, y, z))
    for key, smooth in (("smooth", True), ("raw", False)):
        try:
            t0 = time.perf_counter()
            s = ReverseEngineering.approxSurface(Points=pts, UDegree=3, VDegree=3, NbUPoles=poles, NbVPoles=poles, Smooth=smooth)
            dt = time.perf_counter() - t0
            Part.Face(s).exportBrep("%s/case%d_%s.brep" % (folder, k, key))
            times.append("case%d_%s %.6f" % (k, key, dt))
        except Exception:
            sys.stderr.write("case%d %s: %s\n" % (k, key, traceback.format_exc()))
with open("%s/approx_times.txt" % folder, "w") as f:
    f.write("\n".join(times) + "\n")
