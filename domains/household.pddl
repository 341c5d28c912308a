; Household domain of VAP-TAMP (paper Tables I and II), typed STRIPS with negative-free
; preconditions so that any classical planner accepts it.
;
; Modelling choices, each for a reason:
; * Where the robot stands (robot_in a room, robot_at a thing) comes from localization; what it
;   sees (inview) from perception. `find` and `navigate` move both, and drop the old view, so a
;   plan never relies on something it looked at rooms ago; an inview the camera denies can be
;   corrected without losing track of where the robot is.
; * Items lie `on` surfaces (each room has a floor, where dropped things end up) or `inside`
;   containers. `grasp` takes from a surface, `takeout` from an open container: STRIPS has no
;   disjunction, and both run the same grasp skill with the same Table II situations.
; * `closed` is kept beside `open` so that `close` has a positive effect a camera can confirm.
; * `in_room` of an item is removed while it is held and re-added where it is put down.
; * `clear`, `openable`, `fillable`, `connects` are rigid: no action changes them.
(define (domain household)
  (:requirements :strips :typing)
  (:types
    room thing - object
    item furniture door - thing
    knife - item
    surface container sink - furniture
    appliance - container)

  (:predicates
    (robot_in ?r - room)
    (in_room ?x - thing ?r - room)
    (connects ?d - door ?from - room ?to - room)
    (robot_at ?x - thing)
    (inview ?x - thing)
    (on ?o - item ?s - surface)
    (inside ?o - item ?c - container)
    (holding ?o - item)
    (hand_empty)
    (open ?x - thing)
    (closed ?x - thing)
    (openable ?x - thing)
    (reachable ?o - item)
    (blocking ?b - item ?o - item)
    (clear ?s - surface)
    (fillable ?o - item)
    (filled ?o - item)
    (sliced ?o - item)
    (turned_on ?a - appliance)
    (heated ?o - item))

  (:action navigate
    :parameters (?from - room ?to - room ?d - door ?f - thing)
    :precondition (and (robot_in ?from) (connects ?d ?from ?to) (open ?d) (robot_at ?f))
    :effect (and (robot_in ?to) (not (robot_in ?from))
                 (not (robot_at ?f)) (not (inview ?f)) (robot_at ?d) (inview ?d)))

  (:action find
    :parameters (?from - thing ?to - thing ?r - room)
    :precondition (and (robot_in ?r) (in_room ?to ?r) (robot_at ?from))
    :effect (and (not (robot_at ?from)) (not (inview ?from)) (robot_at ?to) (inview ?to)))

  (:action grasp
    :parameters (?o - item ?s - surface ?r - room)
    :precondition (and (inview ?o) (hand_empty) (reachable ?o) (on ?o ?s) (in_room ?o ?r))
    :effect (and (holding ?o) (not (hand_empty)) (not (on ?o ?s)) (not (in_room ?o ?r))))

  (:action takeout
    :parameters (?o - item ?c - container ?r - room)
    :precondition (and (inview ?c) (open ?c) (hand_empty) (inside ?o ?c) (in_room ?o ?r))
    :effect (and (holding ?o) (not (hand_empty)) (not (inside ?o ?c)) (not (in_room ?o ?r))))

  (:action placeon
    :parameters (?o - item ?s - surface ?r - room)
    :precondition (and (holding ?o) (inview ?s) (clear ?s) (robot_in ?r) (in_room ?s ?r))
    :effect (and (on ?o ?s) (in_room ?o ?r) (hand_empty) (not (holding ?o))))

  (:action placein
    :parameters (?o - item ?c - container ?r - room)
    :precondition (and (holding ?o) (inview ?c) (open ?c) (robot_in ?r) (in_room ?c ?r))
    :effect (and (inside ?o ?c) (in_room ?o ?r) (hand_empty) (not (holding ?o))))

  ; Table I: open and close need only the thing in view. Requiring (closed ?x) would leave no
  ; plan for a leaf the camera found neither open nor closed (a door left ajar).
  (:action open
    :parameters (?x - thing)
    :precondition (and (inview ?x) (openable ?x))
    :effect (and (open ?x) (not (closed ?x))))

  (:action close
    :parameters (?x - thing)
    :precondition (and (inview ?x) (openable ?x))
    :effect (and (closed ?x) (not (open ?x))))

  (:action turnon
    :parameters (?a - appliance ?o - item)
    :precondition (and (inview ?a) (inside ?o ?a))
    :effect (and (turned_on ?a) (heated ?o)))

  (:action cut
    :parameters (?o - item ?k - knife)
    :precondition (and (inview ?o) (holding ?k))
    :effect (sliced ?o))

  (:action fill
    :parameters (?o - item ?s - sink)
    :precondition (and (holding ?o) (fillable ?o) (inview ?s))
    :effect (and (filled ?o) (not (heated ?o))))  ; fresh water is cold

  (:action push
    :parameters (?b - item ?o - item)
    :precondition (and (inview ?o) (hand_empty) (blocking ?b ?o))
    :effect (and (not (blocking ?b ?o)) (reachable ?o)))
)
