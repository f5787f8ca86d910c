"""One run of `./relight bench mpi`, under `mpiexec -np R pvbatch --mpi`: meshes SCENE as read
(all on rank 0) to at most ELEMENTS elements and solves it with THREADS threads per rank.
Prints the solve's wall time on rank 0; every rank's solver logs its share (INFO)."""

import sys
import time

from paraview.simple import LightTaggedRadiosity, RadiosityMesher, XMLPolyDataReader

scene_path, elements, threads = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
scene = XMLPolyDataReader(FileName=[scene_path])
mesher = RadiosityMesher(Input=scene, MaximumElements=elements, PatchSize=0.5, ElementSize=0.01)
mesher.UpdatePipeline()
solver = LightTaggedRadiosity(Input=mesher, NumberOfThreads=threads)
start = time.perf_counter()
solver.UpdatePipeline()
print(f"BENCH solve {time.perf_counter() - start:.4f} s, "
      f"{mesher.GetDataInformation().GetNumberOfCells()} elements", flush=True)
