#!/usr/bin/env python3
# Per drive of an `experiment paper` / `run` folder: ATE, RPE, loop closures and how many of
# them are false (keyframes > 8 m apart in the ground truth), largest raw error, drift per
# street kind. Usage: bench/loop_closure_check.py OUT_DIR (with drives/ and eval/). Prints Markdown.
import json,sys,bisect,math,glob,os
base=sys.argv[1]
def tum(p): return [list(map(float,l.split())) for l in open(p) if l.strip() and not l.startswith('#')]
rows=[]
for ev in sorted(glob.glob(base+'/eval/*')):
    name=os.path.basename(ev); dr=base+'/drives/'+name
    if not os.path.exists(ev+'/metrics.json'): continue
    m=json.load(open(ev+'/metrics.json')); gt=tum(dr+'/groundtruth.tum'); ts=[x[0] for x in gt]
    at=lambda t: gt[min(bisect.bisect_left(ts,t-1e-6),len(gt)-1)]
    bad=sum(1 for L in m['loops'] if math.dist(at(L['t_old'])[1:3],at(L['t_new'])[1:3])>8)
    est=tum(ev+'/estimate.tum'); mx=0
    for e in est[::20]:
        g=at(e[0]); mx=max(mx,math.dist(e[1:3],g[1:3]))
    d=m.get('drift_by_label',{})
    rows.append((name,m['evaluated_length_m']/1000,m['ate_rmse_m'],m['rpe_trans_pct'],m['loop_closures'],bad,mx,
                 '/'.join('%.2f'%d[k]['drift_pct'] if k in d else '-' for k in ('rich','wall','open'))))
print('| drive | km | ATE RMSE [m] | RPE [%] | loop closures | of them false (GT > 8 m apart) | max raw error [m] | drift rich/wall/open [%] |')
print('|---|---|---|---|---|---|---|---|')
for r in rows: print('| %s | %.1f | %.2f | %.2f | %d | %d | %.1f | %s |'%r)
