"""Experiment (reverted): one VV per POI on one thread, phases and refine rays, volumes saved to /tmp/vols_<VT_INDEX>.npy.

    VISTRACK_BUILD_DIR=build/dev python3 bench/experiment_sphere_index.py one 10          # Embree
    VT_INDEX=1 VISTRACK_BUILD_DIR=build/dev python3 bench/experiment_sphere_index.py one 10  # the index
"""
import sys, time, os
from pathlib import Path
REPO=Path('/work/main'); sys.path.insert(0, str(REPO/'tests'/'python'))
import conftest
import numpy as np, vistrack as vt
from vistrack import _core
vt.keep_freed_memory()
data=REPO.parent/'shared'/'data'
env = vt.Environment.from_mesh(str(data / "charlotte" / "uptown_charlotte.obj"), up="y")
scene = vt.VisibilityScene(env)
poi = vt.PoiPath.from_csv(str(data / "charlotte" / "paths" / "paper_slow.csv"), speed=5.0)
pts=[poi.position(t) for t in np.linspace(0.0, poi.duration, 10)]
par = sys.argv[1]=='par'
vols=[]; walls=[]; ph={k:[] for k in ['bounds_s','trace_s','refine_s','mesh_s','embree_s']}; rays=[]
for rep in range(int(sys.argv[2])):
  for p in pts:
    t0=time.perf_counter(); vv,c=_core.visibility_volume_cost(scene, p, 400.0, None, 1.0, par); t1=time.perf_counter()
    walls.append(t1-t0)
    for k in ph: ph[k].append(getattr(c,k))
    if rep==0: vols.append(vv.volume); rays.append(c.refine_rays)
print('wall %.3f'%(np.median(walls)*1e3), ' '.join('%s %.3f'%(k,np.median(v)*1e3) for k,v in ph.items()), 'rays', np.mean(rays))
np.save('/tmp/vols_%s.npy'%os.environ.get('VT_INDEX','no'), np.array(vols))
