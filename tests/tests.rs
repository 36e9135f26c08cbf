mod cli;
mod scene_loader;
mod tracers;
