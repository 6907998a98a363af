"""trimkit-batch: many CAD files (or one big assembly) converted on a Dask distributed
cluster, resumable through a JSON-lines manifest.

    trimkit-batch INPUT... --out DIR [--format glb|ply|obj|stl|blend] [--tolerance T] [--relative]
                  [--check] [--split files|parts] [--workers N | --scheduler tcp://HOST:PORT]
                  [--timeout S] [--manifest FILE]

Modules, one concept each:
  settings      what a conversion is asked for (stored in the manifest, compared on rerun)
  inputs        INPUT arguments to jobs (input file, output file)
  manifest      the JSON-lines record of every input, and what a rerun may skip
  outcome       what a task reports about one input (its half of a manifest line)
  outputs       writing an output under a temporary name and renaming it
  model_cache   the last model read, kept by the process that converts
  convert       one file to one mesh file, as `trimkit mesh` writes it
  parts         --split parts: an assembly meshed one unique part per task, then placed
  isolated      the child process per worker thread that conversions run in (timeouts, crashes)
  tasks         the functions Dask runs on workers
  blend         .blend output: Blender in background on a chunk of files
  blender_chunk the script Blender runs on that chunk
  driver        the cluster: submitting tasks, collecting results into the manifest
  progress      the terminal progress line
  cli           argument parsing and the entry point
"""
