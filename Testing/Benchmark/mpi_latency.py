"""Run by `./relight bench mpi` as `mpiexec -np R pvbatch --mpi --symmetric`: the time of one
sum over the ranks (AllReduce of a shot's table, 75 doubles) with every rank waiting for it,
so the bench can tell transfers from waiting for a slower rank."""

import time

from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController

controller = vtkMultiProcessController.GetGlobalController()
send, receive = vtkDoubleArray(), vtkDoubleArray()
send.SetNumberOfTuples(75)
send.Fill(1.0)
receive.SetNumberOfTuples(75)
for count in (100, 5000):  # the first round warms the connections up
    controller.Barrier()
    start = time.perf_counter()
    for _ in range(count):
        controller.AllReduce(send, receive, vtkCommunicator.SUM_OP)
    seconds = (time.perf_counter() - start) / count
if controller.GetLocalProcessId() == 0:
    print(f"LATENCY {seconds * 1e6:.2f} us", flush=True)
