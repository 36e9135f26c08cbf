patch_loader.v
patch_cache.v
screener.v
intersection_unit.v
processing_element.v
fwft_fifo.v
job_queue.v
memory_arbiter.v
