mod cli;
mod cosim;
mod hardware;
mod scene_loader;
mod tracers;
mod workstream;
