/* Counts what a process sends through MPI (PMPI interposition), for the measurements of
 * README.md, "Communication volume": point-to-point messages and bytes (every blocking and
 * non-blocking send mode) and the calls and bytes of the reductions and other collectives
 * (bytes = the process's contribution). Printed at MPI_Finalize, one line per rank, to stderr.
 *
 *   mpicc -shared -fPIC -O2 -o libmpi_traffic.so mpi_traffic.c
 *   mpirun -np 4 -x LD_PRELOAD=$PWD/libmpi_traffic.so perideal-solid case.prm
 *
 * Two runs that differ only in the number of steps give the traffic per step as the difference
 * over the difference of the steps (the set-up's traffic cancels). */
#include <mpi.h>
#include <stdio.h>

static unsigned long long p2p_messages, p2p_bytes, collective_calls, collective_bytes;

static void count_p2p(int count, MPI_Datatype type)
{
  int size;
  PMPI_Type_size(type, &size);
  ++p2p_messages;
  p2p_bytes += (unsigned long long)count * size;
}

static void count_collective(int count, MPI_Datatype type)
{
  int size;
  PMPI_Type_size(type, &size);
  ++collective_calls;
  collective_bytes += (unsigned long long)count * size;
}

#define SEND_WRAPPER(NAME)                                                                    \
  int NAME(const void *buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm)   \
  {                                                                                           \
    count_p2p(count, type);                                                                   \
    return P##NAME(buf, count, type, dest, tag, comm);                                        \
  }
#define ISEND_WRAPPER(NAME)                                                                   \
  int NAME(const void *buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm,   \
           MPI_Request *request)                                                              \
  {                                                                                           \
    count_p2p(count, type);                                                                   \
    return P##NAME(buf, count, type, dest, tag, comm, request);                               \
  }
SEND_WRAPPER(MPI_Send)
SEND_WRAPPER(MPI_Rsend)
SEND_WRAPPER(MPI_Ssend)
SEND_WRAPPER(MPI_Bsend)
ISEND_WRAPPER(MPI_Isend)
ISEND_WRAPPER(MPI_Irsend)
ISEND_WRAPPER(MPI_Issend)
ISEND_WRAPPER(MPI_Ibsend)

int MPI_Allreduce(const void *in, void *out, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm)
{
  count_collective(count, type);
  return PMPI_Allreduce(in, out, count, type, op, comm);
}

int MPI_Reduce(const void *in, void *out, int count, MPI_Datatype type, MPI_Op op, int root,
               MPI_Comm comm)
{
  count_collective(count, type);
  return PMPI_Reduce(in, out, count, type, op, root, comm);
}

int MPI_Bcast(void *buf, int count, MPI_Datatype type, int root, MPI_Comm comm)
{
  count_collective(count, type);
  return PMPI_Bcast(buf, count, type, root, comm);
}

int MPI_Allgather(const void *in, int count, MPI_Datatype type, void *out, int out_count,
                  MPI_Datatype out_type, MPI_Comm comm)
{
  count_collective(count, type);
  return PMPI_Allgather(in, count, type, out, out_count, out_type, comm);
}

int MPI_Exscan(const void *in, void *out, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm)
{
  count_collective(count, type);
  return PMPI_Exscan(in, out, count, type, op, comm);
}

int MPI_Barrier(MPI_Comm comm)
{
  ++collective_calls;
  return PMPI_Barrier(comm);
}

int MPI_Finalize(void)
{
  int rank;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  fprintf(stderr,
          "mpi_traffic rank %d: p2p messages %llu bytes %llu collectives %llu bytes %llu\n",
          rank, p2p_messages, p2p_bytes, collective_calls, collective_bytes);
  return PMPI_Finalize();
}
