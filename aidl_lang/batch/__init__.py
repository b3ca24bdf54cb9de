"""``aidl batch``: compile many programs, one result row each (docs/batch.md).

* :mod:`.inputs`: files, folders and JSONL rows -> tasks (id, source, hash, options);
* :mod:`.row`: one task -> one row (compile, degrees of freedom, parts, holes, bounding box,
  area, times, renders);
* :mod:`.child`: the warm worker process that compiles task after task, and :class:`Slot`,
  its handle with the hard per-task time-out;
* :mod:`.local`: the local engine, a pool of those workers;
* :mod:`.cluster`: the Dask engine (``--scheduler``), the same rows on a ``dask.distributed``
  cluster;
* :mod:`.store`: the JSONL journal, the Parquet file, resuming;
* :mod:`.command`: the command line, the progress bar and the summary.

Needs the ``batch`` extra (rich; pyarrow for Parquet) and, for ``--scheduler``, the ``dask``
extra.
"""
